#include "sim/mip_texture.h"

#include <opencv2/imgproc.hpp>

namespace parkloc::sim {

namespace {
bool isPowerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }
}  // namespace

MipTexture::MipTexture(const cv::Mat& level0_u8, bool wrap) : wrap_(wrap) {
  CV_Assert(level0_u8.type() == CV_8UC1 && !level0_u8.empty());
  std::vector<cv::Mat> mats{level0_u8.clone()};
  while (mats.back().cols > 1 && mats.back().rows > 1) {
    // Each texel of the next level averages a 2x2 block, so texel j of level l is centred
    // on level-0 coordinate 2^l (j + 0.5) - 0.5 as bilinear() assumes (pyrDown would shift
    // it by half a texel per level). Odd sizes are padded (wrapped or replicated) first.
    const cv::Mat& prev = mats.back();
    cv::Mat even;
    cv::copyMakeBorder(prev, even, 0, prev.rows % 2, 0, prev.cols % 2,
                       wrap ? cv::BORDER_WRAP : cv::BORDER_REPLICATE);
    cv::Mat next;
    cv::resize(even, next, cv::Size(even.cols / 2, even.rows / 2), 0, 0, cv::INTER_AREA);
    mats.push_back(next);
  }
  for (size_t l = 0; l < mats.size(); ++l) {
    Level level;
    // bilinear() indexes rows as data + y * width.
    level.texels = mats[l].isContinuous() ? mats[l] : mats[l].clone();
    level.width = level.texels.cols;
    level.height = level.texels.rows;
    level.scale = 1.0f / static_cast<float>(1 << l);
    level.pow2 = isPowerOfTwo(level.width) && isPowerOfTwo(level.height);
    levels_.push_back(level);
  }
}

MipTexturePair::MipTexturePair(const MipTexture& first, const MipTexture& second) {
  CV_Assert(!first.wraps() && !second.wraps() && first.width() == second.width() &&
            first.height() == second.height() && first.levelCount() == second.levelCount());
  for (int l = 0; l < first.levelCount(); ++l) {
    Level level;
    cv::merge(std::vector<cv::Mat>{first.levelTexels(l), second.levelTexels(l)}, level.texels);
    level.width = level.texels.cols;
    level.height = level.texels.rows;
    level.scale = 1.0f / static_cast<float>(1 << l);
    levels_.push_back(level);
  }
}

}  // namespace parkloc::sim
