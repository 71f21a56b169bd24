#include "eval/birds_eye_evaluation.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "common/error.h"
#include "eval/conditions.h"
#include "eval/latency.h"
#include "io/sequence.h"
#include "map/placed_texts.h"

namespace parkloc::eval {
namespace fs = std::filesystem;

const std::vector<std::string>& birdsEyeOrientations() {
  static const std::vector<std::string> names = {"avm_rot0", "avm_rot90", "avm_rot180",
                                                 "avm_rot270"};
  return names;
}

io::ImageLabels turnLabels(const io::ImageLabels& labels, int quarter_turns) {
  const int turns = ((quarter_turns % 4) + 4) % 4;
  io::ImageLabels out = labels;
  const double w = labels.width, h = labels.height;
  // cv::rotate's clockwise quarter turn maps (x, y) to (h - 1 - y, x).
  auto turn = [&](Eigen::Vector2d p) {
    double cw = w, ch = h;
    for (int k = 0; k < turns; ++k) {
      p = Eigen::Vector2d(ch - 1.0 - p.y(), p.x());
      std::swap(cw, ch);
    }
    return p;
  };
  if (turns % 2 == 1) std::swap(out.width, out.height);
  for (io::LabelInstance& inst : out.instances) {
    for (auto& p : inst.polygon) p = turn(p);
    if (inst.visible_polygon)
      for (auto& p : *inst.visible_polygon) p = turn(p);
    inst.rotation_deg = std::remainder(inst.rotation_deg + 90.0 * turns, 360.0);
  }
  return out;
}

OcrEvaluation evaluateBirdsEye(const std::vector<std::string>& sequences,
                               const BirdsEyeSpotter& spot, const OcrRunOptions& options) {
  OcrEvaluator evaluator(options.metrics);
  const cv::RotateFlags flags[] = {cv::ROTATE_90_CLOCKWISE, cv::ROTATE_180,
                                   cv::ROTATE_90_COUNTERCLOCKWISE};
  for (size_t s = 0; s < sequences.size(); ++s) {
    const io::Sequence seq(sequences[s]);
    const fs::path dir = fs::path(seq.dir()) / "birdseye";
    if (!fs::is_directory(dir / "labels"))
      throw InputError(seq.dir() +
                       ": no birdseye/labels (render with `parkloc simulate --birdseye`)");
    std::vector<fs::path> label_files;
    for (const auto& e : fs::directory_iterator(dir / "labels"))
      if (e.path().extension() == ".json") label_files.push_back(e.path());
    std::sort(label_files.begin(), label_files.end());
    if (options.max_frames_per_sequence && label_files.size() > options.max_frames_per_sequence)
      label_files.resize(options.max_frames_per_sequence);
    const std::vector<std::string> look =
        sequenceConditions(seq.metaJson(), seq.dir() + "/meta.json");
    ocr::SpotRequest request;
    if (options.use_lexicon) {
      request.lexicon = map::distinctTexts(seq.map());
      request.floor_lexicon = map::distinctTexts(seq.map(), /*floor_only=*/true);
    }
    const std::string stage = fmt::format("sequence {}/{} {}", s + 1, sequences.size(),
                                          fs::path(seq.dir()).filename().string());
    for (size_t i = 0; i < label_files.size(); ++i) {
      const io::ImageLabels labels = io::loadLabels(label_files[i].string());
      const fs::path image_path = dir / "images" / (label_files[i].stem().string() + ".jpg");
      const cv::Mat image = cv::imread(image_path.string(), cv::IMREAD_COLOR);
      if (image.empty()) throw IoError("cannot read " + image_path.string());
      for (int turns = 0; turns < 4; ++turns) {
        // A fresh image per turn: rotating into a header of `image` would turn it in place.
        cv::Mat turned;
        if (turns == 0)
          turned = image;
        else
          cv::rotate(image, turned, flags[turns - 1]);
        std::vector<std::string> conditions = look;
        conditions.push_back(birdsEyeOrientations()[static_cast<size_t>(turns)]);
        const auto start = std::chrono::steady_clock::now();
        const std::vector<ocr::TextInstance> found = spot(turned, request);
        evaluator.add(turnLabels(labels, turns), found, conditions, msSince(start) / 1000.0);
      }
      if (options.progress) options.progress({stage, i + 1, label_files.size()});
    }
  }
  return evaluator.result();
}

}  // namespace parkloc::eval
