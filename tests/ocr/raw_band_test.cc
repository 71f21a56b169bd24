#include "ocr/raw_band.h"

#include <gtest/gtest.h>

#include "common/error.h"

namespace parkloc::ocr {
namespace {

TEST(RawBand, RowsAreMultiplesOf32InsideTheImage) {
  const cv::Rect r = bandRect(RawBand{}, {1280, 800});
  EXPECT_EQ(r, cv::Rect(0, 64, 1280, 448));
  // Another resolution keeps the band's place: 0.08 and 0.64 of 400 rows round to 32, 256.
  EXPECT_EQ(bandRect(RawBand{}, {640, 400}), cv::Rect(0, 32, 640, 224));
  // The whole height, and a band too thin to hold one detector stride.
  EXPECT_EQ(bandRect({0.0, 1.0}, {100, 64}), cv::Rect(0, 0, 100, 64));
  EXPECT_EQ(bandRect({0.50, 0.51}, {1280, 800}).height, 32);
  EXPECT_EQ(bandRect({0.99, 1.0}, {1280, 800}), cv::Rect(0, 768, 1280, 32));
}

TEST(RawBand, ABandOutsideTheImageIsAnInputError) {
  EXPECT_THROW(bandRect({-0.1, 0.5}, {1280, 800}), InputError);
  EXPECT_THROW(bandRect({0.2, 1.5}, {1280, 800}), InputError);
  EXPECT_THROW(bandRect({0.6, 0.6}, {1280, 800}), InputError);
  EXPECT_THROW(checkBand({0.7, 0.6}), InputError);
  EXPECT_NO_THROW(checkBand(RawBand{}));
}

}  // namespace
}  // namespace parkloc::ocr
