#include "ocr/ocr_io.h"

#include <fmt/format.h>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "common/error.h"

namespace parkloc::ocr {

cv::Mat readImage(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw IoError("image not found: " + path);
  if (std::filesystem::file_size(path) == 0) throw InputError("empty image file: " + path);
  cv::Mat image = cv::imread(path, cv::IMREAD_COLOR);
  if (image.empty()) throw InputError("cannot decode image (corrupt or unknown format): " + path);
  return image;
}

std::vector<std::string> loadLexiconFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw IoError("cannot open lexicon " + path);
  std::vector<std::string> out;
  std::string line;
  while (std::getline(in, line)) {
    const auto b = line.find_first_not_of(" \t\r");
    if (b == std::string::npos) continue;
    const auto e = line.find_last_not_of(" \t\r");
    out.push_back(line.substr(b, e - b + 1));
  }
  return out;
}

nlohmann::json toJson(const TextInstance& inst) {
  nlohmann::json polygon = nlohmann::json::array();
  for (const auto& p : inst.polygon) polygon.push_back({p.x, p.y});
  return {{"text", inst.text},
          {"raw_text", inst.raw_text},
          {"lexicon_match", inst.lexicon_match},
          {"second_opinion", inst.second_opinion},
          {"partial", inst.partial},
          {"sized_by_map", inst.sized_by_map},
          {"box_only", inst.box_only},
          {"class", map::toString(inst.cls)},
          {"class_id", static_cast<int>(inst.cls)},
          {"detection_score", inst.detection_score},
          {"recognition_score", inst.recognition_score},
          {"class_score", inst.class_score},
          {"polygon", polygon}};
}

nlohmann::json toJson(const std::vector<TextInstance>& instances) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& inst : instances) out.push_back(toJson(inst));
  return out;
}

std::string describe(const TextInstance& inst) {
  std::string corners;
  for (const auto& p : inst.polygon) corners += fmt::format(" ({:.1f},{:.1f})", p.x, p.y);
  return fmt::format("{:<10} [{}] rec {:.2f} det {:.2f} cls {:.2f} ({}; raw {}){} TL,TR,BR,BL:{}",
                     inst.text.empty() ? "(unread)" : inst.text, map::toString(inst.cls),
                     inst.recognition_score, inst.detection_score, inst.class_score,
                     inst.second_opinion  ? "lexicon, second opinion"
                     : inst.partial       ? "lexicon, by the part that shows"
                     : inst.lexicon_match ? "lexicon"
                     : inst.text.empty()  ? "unread"
                                          : "free",
                     inst.raw_text, inst.sized_by_map ? " sized by the map" : "", corners);
}

cv::Mat drawInstances(const cv::Mat& image, const std::vector<TextInstance>& instances) {
  cv::Mat out = image.clone();
  const cv::Scalar colours[3] = {{255, 160, 0}, {0, 220, 0}, {0, 160, 255}};  // BGR per class
  for (const auto& inst : instances) {
    const cv::Scalar colour = colours[static_cast<int>(inst.cls)];
    std::vector<cv::Point> poly;
    for (const auto& p : inst.polygon) poly.emplace_back(cvRound(p.x), cvRound(p.y));
    cv::polylines(out, poly, true, colour, 1, cv::LINE_AA);
    cv::line(out, poly[0], poly[1], colour, 2, cv::LINE_AA);  // the text's top edge
    cv::circle(out, poly[0], 3, {0, 0, 255}, cv::FILLED, cv::LINE_AA);
    const std::string label =
        inst.text + (inst.lexicon_match ? "" : "?") + " " + map::toString(inst.cls).substr(0, 4);
    const cv::Rect box = cv::boundingRect(poly);
    cv::Point at(box.x, std::max(12, box.y - 4));
    int baseline = 0;
    const cv::Size size = cv::getTextSize(label, cv::FONT_HERSHEY_SIMPLEX, 0.45, 1, &baseline);
    cv::rectangle(out, at + cv::Point(0, baseline), at + cv::Point(size.width, -size.height),
                  cv::Scalar::all(0), cv::FILLED);
    cv::putText(out, label, at, cv::FONT_HERSHEY_SIMPLEX, 0.45, colour, 1, cv::LINE_AA);
  }
  return out;
}

}  // namespace parkloc::ocr
