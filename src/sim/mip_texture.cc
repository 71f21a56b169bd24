#include "sim/mip_texture.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace parkloc::sim {

MipTexture::MipTexture(const cv::Mat& level0_u8, bool wrap) : wrap_(wrap) {
  CV_Assert(level0_u8.type() == CV_8UC1 && !level0_u8.empty());
  levels_.push_back(level0_u8.clone());
  while (levels_.back().cols > 1 && levels_.back().rows > 1) {
    // Each texel of the next level averages a 2x2 block, so texel j of level l is centred
    // on level-0 coordinate 2^l (j + 0.5) - 0.5 as bilinear() assumes (pyrDown would shift
    // it by half a texel per level). Odd sizes are padded (wrapped or replicated) first.
    const cv::Mat& prev = levels_.back();
    cv::Mat even;
    cv::copyMakeBorder(prev, even, 0, prev.rows % 2, 0, prev.cols % 2,
                       wrap ? cv::BORDER_WRAP : cv::BORDER_REPLICATE);
    cv::Mat next;
    cv::resize(even, next, cv::Size(even.cols / 2, even.rows / 2), 0, 0, cv::INTER_AREA);
    levels_.push_back(next);
  }
}

float MipTexture::bilinear(int level, float u, float v) const {
  const cv::Mat& m = levels_[level];
  const float scale = 1.0f / static_cast<float>(1 << level);
  // Level-0 texel centres at integers -> this level's texel centres.
  const float x = (u + 0.5f) * scale - 0.5f;
  const float y = (v + 0.5f) * scale - 0.5f;
  const float fx = std::floor(x), fy = std::floor(y);
  int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
  const float ax = x - fx, ay = y - fy;
  int x1 = x0 + 1, y1 = y0 + 1;
  const int w = m.cols, h = m.rows;
  if (wrap_) {
    if ((w & (w - 1)) == 0 && (h & (h - 1)) == 0) {  // power of two: masks, no division
      x0 &= w - 1;
      y0 &= h - 1;
    } else {
      x0 = ((x0 % w) + w) % w;
      y0 = ((y0 % h) + h) % h;
    }
    x1 = x0 + 1 == w ? 0 : x0 + 1;
    y1 = y0 + 1 == h ? 0 : y0 + 1;
  } else {
    x0 = std::clamp(x0, 0, w - 1);
    x1 = std::clamp(x1, 0, w - 1);
    y0 = std::clamp(y0, 0, h - 1);
    y1 = std::clamp(y1, 0, h - 1);
  }
  const uint8_t* r0 = m.ptr<uint8_t>(y0);
  const uint8_t* r1 = m.ptr<uint8_t>(y1);
  const float top = r0[x0] + ax * (r0[x1] - r0[x0]);
  const float bottom = r1[x0] + ax * (r1[x1] - r1[x0]);
  return (top + ay * (bottom - top)) * (1.0f / 255.0f);
}

float MipTexture::sample(float u, float v, float footprint) const {
  const int last = static_cast<int>(levels_.size()) - 1;
  const float lod = footprint > 1.0f ? std::log2(footprint) : 0.0f;
  const int l0 = std::min(static_cast<int>(lod), last);
  if (l0 >= last) return bilinear(last, u, v);
  const float t = lod - static_cast<float>(l0);
  const float a = bilinear(l0, u, v);
  if (t < 0.02f) return a;
  return a + t * (bilinear(l0 + 1, u, v) - a);
}

float MipTexture::sampleNearestLevel(float u, float v, float footprint) const {
  const int last = static_cast<int>(levels_.size()) - 1;
  const float lod = footprint > 1.0f ? std::log2(footprint) + 0.5f : 0.0f;
  return bilinear(std::min(static_cast<int>(lod), last), u, v);
}

}  // namespace parkloc::sim
