#pragma once
// A single-channel 8-bit texture with a mip pyramid, for filtered lookups: the level is
// chosen from the footprint of a pixel on the surface, so far text is not aliased and near
// text stays sharp.
#include <opencv2/core.hpp>
#include <vector>

namespace parkloc::sim {

class MipTexture {
 public:
  MipTexture() = default;
  // `wrap`: the texture tiles (floor concrete); otherwise texels outside read as the border.
  explicit MipTexture(const cv::Mat& level0_u8, bool wrap = false);

  bool empty() const { return levels_.empty(); }
  int width() const { return levels_.empty() ? 0 : levels_[0].cols; }
  int height() const { return levels_.empty() ? 0 : levels_[0].rows; }

  // Value in [0, 1] at level-0 texel coordinates (u, v) (texel centres at integers), for a
  // pixel footprint of `footprint` level-0 texels: trilinear between the two nearest levels.
  float sample(float u, float v, float footprint) const;
  // Bilinear at a single level (the nearest one), cheaper for large low-contrast textures.
  float sampleNearestLevel(float u, float v, float footprint) const;

 private:
  float bilinear(int level, float u, float v) const;

  std::vector<cv::Mat> levels_;
  bool wrap_ = false;
};

}  // namespace parkloc::sim
