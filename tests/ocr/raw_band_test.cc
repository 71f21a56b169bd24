#include "ocr/raw_band.h"

#include <gtest/gtest.h>

#include "common/error.h"
#include "geometry/rig.h"
#include "scaled_camera.h"

namespace parkloc::ocr {
namespace {

RawBand band(double top, double bottom) {
  RawBand b;
  b.top = top;
  b.bottom = bottom;
  return b;
}

// The default rig's band: rows [64, 512) of its 800.
TEST(RawBand, TheDefaultRigsBandIsRows64To512) {
  const auto model = geometry::defaultRig().cameras[0].model;
  EXPECT_EQ(bandRect(RawBand{}, model), cv::Rect(0, 64, 1280, 448));
  EXPECT_DOUBLE_EQ(bandScale(RawBand{}, model), 1.0);
}

// The band follows the lens, not the pixel count: the same lens imaged at twice the
// resolution (every pixel length doubled) puts it at twice the rows, and its detector scale
// halves, so text reaches the detector as tall as on the default rig.
TEST(RawBand, TheBandScalesWithTheCalibration) {
  auto model = testing::scaledCamera(geometry::defaultRig().cameras[0].model, 2);
  EXPECT_EQ(bandRect(RawBand{}, model), cv::Rect(0, 128, 2560, 896));
  EXPECT_DOUBLE_EQ(bandScale(RawBand{}, model), 0.5);
  // A shorter focal length is detected at its own resolution, never enlarged; 0: never scaled.
  model.fy = 200.0;
  EXPECT_DOUBLE_EQ(bandScale(RawBand{}, model), 1.0);
  RawBand own;
  own.pixels_per_radian = 0.0;
  model.fy = 730.0;
  EXPECT_DOUBLE_EQ(bandScale(own, model), 1.0);
}

TEST(RawBand, RowsAreMultiplesOf32InsideTheImage) {
  const auto model = geometry::defaultRig().cameras[0].model;
  // Edges past the lens' field (1.5 rad > its image's top and bottom): the whole height.
  EXPECT_EQ(bandRect(band(-1.5, 1.5), model), cv::Rect(0, 0, 1280, 800));
  // A band too thin to hold one detector stride, and one at the bottom edge.
  EXPECT_EQ(bandRect(band(0.0, 0.01), model).height, 32);
  EXPECT_EQ(bandRect(band(1.4, 1.5), model), cv::Rect(0, 768, 1280, 32));
  // A pinhole camera: the rows of its rays, tan(angle) * fy from the principal point.
  geometry::CameraModel pinhole;
  pinhole.type = geometry::CameraModelType::kPinhole;
  pinhole.width = 640;
  pinhole.height = 480;
  pinhole.fx = pinhole.fy = 320.0;
  pinhole.cx = 319.5;
  pinhole.cy = 239.5;
  // tan(-0.5) * 320 + 239.5 = 64.7 -> 64; tan(0.3) * 320 + 239.5 = 338.5 -> 352.
  EXPECT_EQ(bandRect(band(-0.5, 0.3), pinhole), cv::Rect(0, 64, 640, 288));
}

TEST(RawBand, ABandOutsideTheLensRangeIsAnInputError) {
  const auto model = geometry::defaultRig().cameras[0].model;
  EXPECT_THROW(bandRect(band(-1.6, 0.5), model), InputError);
  EXPECT_THROW(bandRect(band(0.2, 1.6), model), InputError);
  EXPECT_THROW(bandRect(band(0.6, 0.6), model), InputError);
  EXPECT_THROW(checkBand(band(0.7, 0.6)), InputError);
  RawBand negative;
  negative.pixels_per_radian = -1.0;
  EXPECT_THROW(checkBand(negative), InputError);
  EXPECT_NO_THROW(checkBand(RawBand{}));
}

}  // namespace
}  // namespace parkloc::ocr
