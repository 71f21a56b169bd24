#include "sim/text_raster.h"

#include <algorithm>
#include <opencv2/freetype.hpp>
#include <opencv2/imgproc.hpp>

#include "common/error.h"

namespace parkloc::sim {

TextRasterizer::TextRasterizer() = default;
TextRasterizer::~TextRasterizer() = default;

cv::Mat TextRasterizer::render(const std::string& font_path, const std::string& text,
                               int ink_height_px) {
  auto it = fonts_.find(font_path);
  if (it == fonts_.end()) {
    cv::Ptr<cv::freetype::FreeType2> ft = cv::freetype::createFreeType2();
    try {
      ft->loadFontData(font_path, 0);
    } catch (const cv::Exception&) {
      throw InputError("font '" + font_path + "' cannot be loaded");
    }
    it = fonts_.emplace(font_path, ft).first;
  }
  cv::freetype::FreeType2& ft = *it->second;
  // Font height is em-based; digits and capitals are about 0.73 em, so render a little
  // larger and crop to the ink.
  const int font_height = std::max(8, static_cast<int>(ink_height_px * 1.4));
  int baseline = 0;
  const cv::Size size = ft.getTextSize(text, font_height, -1, &baseline);
  const int margin = font_height / 2 + 4;
  // The FreeType module draws on 3-channel images only.
  cv::Mat colour(size.height + baseline + 2 * margin, size.width + 2 * margin, CV_8UC3,
                 cv::Scalar::all(0));
  ft.putText(colour, text, cv::Point(margin, margin + size.height), font_height,
             cv::Scalar::all(255), -1, cv::LINE_AA, true);
  cv::Mat canvas;
  cv::extractChannel(colour, canvas, 0);
  const cv::Rect ink = cv::boundingRect(canvas > 24);
  if (ink.area() == 0) return cv::Mat(1, 1, CV_8UC1, cv::Scalar(0));
  return canvas(ink).clone();
}

void wearInk(cv::Mat& coverage, double severity, std::mt19937_64& rng) {
  if (severity <= 0.0) return;
  // Low-frequency noise thresholded into erased blotches, plus fine grain.
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  const int cell = std::max(3, coverage.rows / 6);
  cv::Mat coarse(coverage.rows / cell + 2, coverage.cols / cell + 2, CV_32F);
  for (int y = 0; y < coarse.rows; ++y)
    for (int x = 0; x < coarse.cols; ++x) coarse.at<float>(y, x) = static_cast<float>(uni(rng));
  cv::Mat field;
  cv::resize(coarse, field, coverage.size(), 0, 0, cv::INTER_CUBIC);
  cv::Mat grain(coverage.size(), CV_32F);
  for (int y = 0; y < grain.rows; ++y)
    for (int x = 0; x < grain.cols; ++x) grain.at<float>(y, x) = static_cast<float>(uni(rng));
  cv::GaussianBlur(grain, grain, cv::Size(0, 0), 1.0);
  const float threshold = static_cast<float>(0.75 - 0.45 * severity);
  for (int y = 0; y < coverage.rows; ++y) {
    uint8_t* c = coverage.ptr<uint8_t>(y);
    const float* f = field.ptr<float>(y);
    const float* g = grain.ptr<float>(y);
    for (int x = 0; x < coverage.cols; ++x) {
      const float erase = std::clamp((f[x] - threshold) * 6.0f, 0.0f, 1.0f);
      const float keep =
          (1.0f - erase) * (1.0f - 0.5f * static_cast<float>(severity) *
                                       std::clamp((g[x] - 0.5f) * 4.0f + 0.5f, 0.0f, 1.0f));
      c[x] = cv::saturate_cast<uint8_t>(c[x] * keep);
    }
  }
}

cv::Mat padInk(const cv::Mat& coverage, int pad) {
  cv::Mat out;
  cv::copyMakeBorder(coverage, out, pad, pad, pad, pad, cv::BORDER_CONSTANT, cv::Scalar(0));
  return out;
}

}  // namespace parkloc::sim
