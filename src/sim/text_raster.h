#pragma once
// Text to ink: renders a string with a TrueType font (OpenCV's FreeType module) into an
// 8-bit coverage image cropped tightly to the ink, so that a decal placed with that image
// has its map corners exactly on the visible text box.
#include <map>
#include <memory>
#include <opencv2/core.hpp>
#include <random>
#include <string>

namespace cv::freetype {
class FreeType2;
}

namespace parkloc::sim {

class TextRasterizer {
 public:
  TextRasterizer();
  ~TextRasterizer();
  // Coverage (0 background, 255 ink) of `text` whose ink is about `ink_height_px` tall,
  // cropped to the ink's bounding box. Throws InputError when the font cannot be loaded.
  cv::Mat render(const std::string& font_path, const std::string& text, int ink_height_px);

 private:
  std::map<std::string, cv::Ptr<cv::freetype::FreeType2>> fonts_;
};

// Worn paint: blotches erased from the ink and a lower overall opacity; `severity` in [0, 1].
void wearInk(cv::Mat& coverage, double severity, std::mt19937_64& rng);

// Adds `pad` background texels on every side (so filtered lookups fade out at the edge).
cv::Mat padInk(const cv::Mat& coverage, int pad);

}  // namespace parkloc::sim
