#include "ocr/raw_band.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/error.h"

namespace parkloc::ocr {

void checkBand(const RawBand& band) {
  if (!(band.top >= 0.0 && band.bottom <= 1.0 && band.bottom > band.top))
    throw InputError(fmt::format("raw band [{}, {}): must lie in [0, 1], bottom below top",
                                 band.top, band.bottom));
}

cv::Rect bandRect(const RawBand& band, const cv::Size& size) {
  checkBand(band);
  auto row = [&](double fraction) {
    return static_cast<int>(std::lround(fraction * size.height / 32.0)) * 32;
  };
  // At least one stride tall, however thin the band or low its top.
  const int top = std::clamp(row(band.top), 0, std::max(0, size.height - 32));
  const int bottom = std::clamp(std::max(row(band.bottom), top + 32), 0, size.height);
  return {0, top, size.width, bottom - top};
}

}  // namespace parkloc::ocr
