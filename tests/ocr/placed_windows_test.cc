#include "ocr/placed_windows.h"

#include <gtest/gtest.h>

#include "geometry/rig.h"

namespace parkloc::ocr {
namespace {

// A point on the floor `ahead` metres along the camera's heading and `aside` metres to its
// left, in the vehicle frame.
Eigen::Vector2d besideCamera(const geometry::RigCamera& camera, double ahead, double aside) {
  Eigen::Vector2d forward = camera.vehicle_from_camera.linear().col(2).head<2>().normalized();
  const Eigen::Vector2d left(-forward.y(), forward.x());
  return camera.vehicle_from_camera.translation().head<2>() + forward * ahead + left * aside;
}

map::PlacedText placedAt(const Eigen::Vector2d& xy, const std::string& text = "A001") {
  map::PlacedText placed;
  placed.text = text;
  placed.vehicle_xy = xy;
  return placed;
}

class PlacedWindowsTest : public ::testing::Test {
 protected:
  const geometry::RigCamera camera = *geometry::defaultRig().find("right");
  const GroundView view{camera};
  const GroundView reach{camera, [] {
                           GroundViewOptions o;
                           o.half_width = 10.0;
                           return o;
                         }()};
};

TEST_F(PlacedWindowsTest, ATextInsideTheViewGetsNoWindow) {
  EXPECT_TRUE(windowsBeyondView(view, reach, {placedAt(besideCamera(camera, 2.0, 1.0))}).empty());
}

TEST_F(PlacedWindowsTest, ATextBeyondTheViewGetsAStrideAlignedWindowAroundIt) {
  for (double aside : {-8.0, 8.0}) {
    const Eigen::Vector2d xy = besideCamera(camera, 2.0, aside);
    const auto windows = windowsBeyondView(view, reach, {placedAt(xy)});
    ASSERT_EQ(windows.size(), 1u) << aside;
    const cv::Rect& w = windows[0];
    EXPECT_TRUE(w.contains(reach.viewFromGround(xy))) << aside;
    EXPECT_EQ(w & reach.rect(), w) << aside;
    EXPECT_EQ(w.width % 32, 0);
    EXPECT_EQ(w.height % 32, 0);
    // About the option's 2.4 m side at 1.5 cm a pixel, not the whole reach.
    EXPECT_GE(w.width, 160);
    EXPECT_LE(w.width, 192);
    // Its ground lies beyond the view's side: the window is where the view is not.
    const cv::Point2f centre(w.x + w.width / 2.f, w.y + w.height / 2.f);
    EXPECT_FALSE(view.rect().contains(view.viewFromGround(reach.groundFromView(centre))));
  }
}

TEST_F(PlacedWindowsTest, NeighbouringTextsShareOneWindow) {
  const Eigen::Vector2d a = besideCamera(camera, 2.0, 7.5), b = besideCamera(camera, 2.0, 8.7);
  const auto windows = windowsBeyondView(view, reach, {placedAt(a), placedAt(b, "A002")});
  ASSERT_EQ(windows.size(), 1u);
  EXPECT_TRUE(windows[0].contains(reach.viewFromGround(a)));
  EXPECT_TRUE(windows[0].contains(reach.viewFromGround(b)));
}

TEST_F(PlacedWindowsTest, AtMostMaxTextsGetWindowsTheTallestFirst) {
  const Eigen::Vector2d near_a = besideCamera(camera, 2.0, 7.0),
                        near_b = besideCamera(camera, 2.0, -7.0),
                        far = besideCamera(camera, 2.0, 9.5);
  const std::vector<map::PlacedText> placed = {placedAt(far, "A003"), placedAt(near_a),
                                               placedAt(near_b, "A002")};
  EXPECT_GT(apparentHeightPx(reach, placed[1], 0.45), apparentHeightPx(reach, placed[0], 0.45));
  PlacedWindowOptions options;
  options.min_height_px = 0.0;
  options.max_texts = 0;
  EXPECT_EQ(windowsBeyondView(view, reach, placed, options).size(), 3u);
  options.max_texts = 2;
  const auto windows = windowsBeyondView(view, reach, placed, options);
  ASSERT_EQ(windows.size(), 2u);
  for (const cv::Rect& w : windows) EXPECT_FALSE(w.contains(reach.viewFromGround(far)));
}

TEST_F(PlacedWindowsTest, TextsBeyondTheReachOrBehindTheBodyGetNone) {
  EXPECT_TRUE(windowsBeyondView(view, reach, {placedAt(besideCamera(camera, 2.0, 12.0))}).empty());
  // Under the vehicle: the camera does not see that floor.
  EXPECT_TRUE(windowsBeyondView(view, reach, {placedAt(Eigen::Vector2d(1.5, 0.0))}).empty());
}

TEST_F(PlacedWindowsTest, TextsThatWouldShowTooSmallGetNone) {
  const map::PlacedText near = placedAt(besideCamera(camera, 2.0, 7.0)),
                        far = placedAt(besideCamera(camera, 2.0, 9.5), "A002");
  const double near_px = apparentHeightPx(reach, near, 0.45),
               far_px = apparentHeightPx(reach, far, 0.45);
  ASSERT_GT(near_px, far_px);
  PlacedWindowOptions options;
  options.min_height_px = 0.5 * (near_px + far_px);
  const auto windows = windowsBeyondView(view, reach, {near, far}, options);
  ASSERT_EQ(windows.size(), 1u);
  EXPECT_TRUE(windows[0].contains(reach.viewFromGround(near.vehicle_xy)));
  // Twice as tall a text shows about twice as tall.
  EXPECT_NEAR(apparentHeightPx(reach, near, 0.9) / near_px, 2.0, 0.1);
}

TEST_F(PlacedWindowsTest, AMosaicLaysWindowsSideBySideAndMapsItsPixelsBackToTheView) {
  cv::Mat raw(camera.model.height, camera.model.width, CV_8UC3);
  cv::randu(raw, cv::Scalar::all(0), cv::Scalar::all(256));
  const std::vector<cv::Rect> windows = {{64, 32, 160, 128}, {512, 96, 96, 160}};
  const WindowMosaic mosaic = mosaicOf(reach, raw, windows, 32);
  ASSERT_EQ(mosaic.tiles.size(), 2u);
  EXPECT_EQ(mosaic.image.size(), cv::Size(160 + 32 + 96, 160));
  for (size_t i = 0; i < windows.size(); ++i) {
    const cv::Rect& tile = mosaic.tiles[i];
    EXPECT_EQ(tile.size(), windows[i].size());
    EXPECT_EQ(cv::norm(mosaic.image(tile), reach.render(raw, windows[i]), cv::NORM_INF), 0.0);
    // A pixel of the tile maps to the same pixel of the window in the view.
    const cv::Point2f inside(tile.x + 10.5f, tile.y + 20.25f);
    const auto shift = mosaic.shiftAt(inside);
    ASSERT_TRUE(shift);
    EXPECT_EQ(inside + *shift, cv::Point2f(windows[i].x + 10.5f, windows[i].y + 20.25f));
  }
  EXPECT_FALSE(mosaic.shiftAt({160 + 16.f, 10.f}));  // the gap
  EXPECT_FALSE(mosaic.shiftAt({100.f, 140.f}));      // below the first, shorter tile
  EXPECT_TRUE(mosaicOf(reach, raw, {}).image.empty());
}

}  // namespace
}  // namespace parkloc::ocr
