#include "ocr/raw_band.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/error.h"

namespace parkloc::ocr {

void checkBand(const RawBand& band) {
  const bool inside = std::abs(band.top) <= 1.5 && std::abs(band.bottom) <= 1.5;
  if (!(inside && band.bottom > band.top))
    throw InputError(fmt::format(
        "raw band [{}, {}]: edges must lie within 1.5 radians of the axis, bottom below top",
        band.top, band.bottom));
  if (!(band.pixels_per_radian >= 0.0))
    throw InputError(
        fmt::format("raw band: pixels_per_radian {} must be 0 or positive", band.pixels_per_radian));
}

cv::Rect bandRect(const RawBand& band, const geometry::CameraModel& camera) {
  checkBand(band);
  const int height = camera.height;
  // The row where the ray `angle` radians below the axis meets the image; beyond the lens'
  // field, the border it lies toward.
  auto rowOf = [&](double angle) {
    const auto px = camera.project(Eigen::Vector3d(0.0, std::sin(angle), std::cos(angle)));
    const double row = px ? px->y() : (angle < 0.0 ? 0.0 : height);
    return static_cast<int>(std::lround(std::clamp(row, 0.0, double(height)) / 32.0)) * 32;
  };
  // At least one stride tall, however thin the band or low its top.
  const int top = std::clamp(rowOf(band.top), 0, std::max(0, height - 32));
  const int bottom = std::clamp(std::max(rowOf(band.bottom), top + 32), 0, height);
  return {0, top, camera.width, bottom - top};
}

double bandScale(const RawBand& band, const geometry::CameraModel& camera) {
  if (band.pixels_per_radian <= 0.0 || camera.fy <= 0.0) return 1.0;
  return std::min(1.0, band.pixels_per_radian / camera.fy);
}

}  // namespace parkloc::ocr
