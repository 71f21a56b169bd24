#include "ocr/ground_view.h"

#include <gtest/gtest.h>

#include <random>

#include "geometry/rig.h"
#include "scaled_camera.h"

namespace parkloc::ocr {
namespace {

TEST(GroundView, ViewPixelsMapToTheRawPixelsOfTheirGroundPoints) {
  const auto rig = geometry::defaultRig();
  for (const auto& camera : rig.cameras) {
    GroundViewOptions options;
    const GroundView view(camera, options);
    EXPECT_EQ(view.size().width % 32, 0);
    EXPECT_EQ(view.size().height % 32, 0);
    // A raw image whose pixel values encode their own coordinates: the view must sample
    // each view pixel from rawFromView of that pixel.
    cv::Mat raw(camera.model.height, camera.model.width, CV_8UC3);
    for (int y = 0; y < raw.rows; ++y)
      for (int x = 0; x < raw.cols; ++x)
        raw.at<cv::Vec3b>(y, x) = cv::Vec3b(x % 256, y % 256, (x / 256) * 16 + y / 256);
    const cv::Mat rendered = view.render(raw);
    int checked = 0;
    for (int r = 8; r < view.size().height; r += 41)
      for (int c = 8; c < view.size().width; c += 37) {
        const auto px = view.rawFromView(cv::Point2f(c, r));
        if (!px || px->x < 1 || px->y < 1 || px->x > raw.cols - 2 || px->y > raw.rows - 2) continue;
        const cv::Point ip(cvRound(px->x), cvRound(px->y));
        // Only where the nearest raw pixel is close to the sample point (little blending),
        // and not next to where the coding wraps around (255 beside 0).
        if (std::abs(px->x - ip.x) > 0.1f || std::abs(px->y - ip.y) > 0.1f) continue;
        if ((ip.x + 1) % 256 < 2 || (ip.y + 1) % 256 < 2) continue;
        EXPECT_EQ(rendered.at<cv::Vec3b>(r, c), raw.at<cv::Vec3b>(ip)) << camera.name;
        ++checked;
      }
    // Points on the floor straight ahead of the camera are visible in its view.
    EXPECT_TRUE(view.rawFromView(cv::Point2f(view.size().width / 2.f, view.size().height / 2.f)))
        << camera.name;
    EXPECT_GT(checked, 3) << camera.name;
  }
}

TEST(GroundView, RawPixelsMapBackToTheirViewPixels) {
  for (const auto& camera : geometry::defaultRig().cameras) {
    const GroundView view(camera);
    int checked = 0;
    for (int r = 5; r < view.size().height; r += 53)
      for (int c = 5; c < view.size().width; c += 47) {
        const cv::Point2f v(c + 0.25f, r + 0.75f);
        const auto raw = view.rawFromView(v);
        if (!raw || !camera.model.inImage(Eigen::Vector2d(raw->x, raw->y))) continue;
        const auto back = view.viewFromRaw(*raw);
        ASSERT_TRUE(back) << camera.name << " view pixel " << v;
        EXPECT_NEAR(back->x, v.x, 0.05) << camera.name << " view pixel " << v;
        EXPECT_NEAR(back->y, v.y, 0.05) << camera.name << " view pixel " << v;
        ++checked;
      }
    EXPECT_GT(checked, 20) << camera.name;
  }
}

TEST(GroundView, GroundPointsMapToViewPixelsAndBack) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coord(-8.0, 8.0);
  for (const auto& camera : geometry::defaultRig().cameras) {
    const GroundView view(camera);
    for (int i = 0; i < 50; ++i) {
      const Eigen::Vector2d g(coord(rng), coord(rng));
      const Eigen::Vector2d back = view.groundFromView(view.viewFromGround(g));
      EXPECT_NEAR(back.x(), g.x(), 1e-4) << camera.name;
      EXPECT_NEAR(back.y(), g.y(), 1e-4) << camera.name;
    }
  }
}

TEST(GroundView, RawPixelsAboveTheHorizonHaveNoViewPixel) {
  for (const auto& camera : geometry::defaultRig().cameras) {
    const GroundView view(camera);
    // A point 10 m out along the camera's heading, 0.5 m above the lens (3 degrees above the
    // horizon, still in the image of the mirror cameras looking 55 degrees down): its ray
    // never meets the floor.
    Eigen::Vector3d heading = camera.vehicle_from_camera.linear().col(2);
    heading.z() = 0.0;
    const Eigen::Vector3d above = camera.vehicle_from_camera.translation() +
                                  10.0 * heading.normalized() + Eigen::Vector3d(0, 0, 0.5);
    const auto px = camera.model.project(camera.vehicle_from_camera.inverse() * above);
    ASSERT_TRUE(px && camera.model.inImage(*px)) << camera.name;
    EXPECT_FALSE(view.viewFromRaw(cv::Point2f(px->x(), px->y()))) << camera.name;
  }
}

TEST(GroundView, AQuadMapsCornerByCornerOrNotAtAll) {
  const geometry::Rig rig = geometry::defaultRig();
  const geometry::RigCamera& camera = rig.cameras.front();
  const GroundView view(camera);
  const Quad in_view = {
      cv::Point2f(100.5f, 80.5f), {160.5f, 82.5f}, {158.5f, 110.5f}, {99.5f, 108.5f}};
  const auto raw = view.rawFromView(in_view);
  ASSERT_TRUE(raw);
  for (size_t k = 0; k < 4; ++k) {
    const auto corner = view.rawFromView(in_view[k]);
    ASSERT_TRUE(corner);
    EXPECT_EQ((*raw)[k], *corner);
  }
  const auto back = view.viewFromRaw(*raw);
  ASSERT_TRUE(back);
  for (size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR((*back)[k].x, in_view[k].x, 0.05);
    EXPECT_NEAR((*back)[k].y, in_view[k].y, 0.05);
  }
  // One corner above the horizon (the raw pixel of a point 10 m out, 0.5 m above the lens):
  // no quad.
  Eigen::Vector3d heading = camera.vehicle_from_camera.linear().col(2);
  heading.z() = 0.0;
  const Eigen::Vector3d above = camera.vehicle_from_camera.translation() +
                                10.0 * heading.normalized() + Eigen::Vector3d(0, 0, 0.5);
  const auto px = camera.model.project(camera.vehicle_from_camera.inverse() * above);
  ASSERT_TRUE(px);
  Quad cut = *raw;
  cut[2] = cv::Point2f(px->x(), px->y());
  EXPECT_FALSE(view.viewFromRaw(cut));
}

TEST(GroundView, TheFloorBehindTheCarsBodyIsLeftOutAndTheViewCroppedToWhatShows) {
  for (const auto& camera : geometry::defaultRig().cameras) {
    ASSERT_TRUE(camera.body) << camera.name;
    geometry::RigCamera bare = camera;
    bare.body.reset();
    const GroundView view(camera), bare_view(bare);
    const Eigen::Vector2d foot = camera.vehicle_from_camera.translation().head<2>();
    const Eigen::Vector2d heading =
        camera.vehicle_from_camera.linear().col(2).head<2>().normalized();
    // Under the car, 0.4 m behind the camera, in the fisheye's field (wider than a
    // half-space): not seen, and its pixel is the one that shows the body.
    const Eigen::Vector2d under = foot - 0.4 * heading;
    EXPECT_FALSE(view.seesTheFloorAt(view.viewFromGround(under))) << camera.name;
    EXPECT_TRUE(view.rawFromView(view.viewFromGround(under))) << camera.name;
    // The mirror cameras, looking down, have it in their image: only the body hides it.
    if (camera.name == "left" || camera.name == "right") {
      EXPECT_TRUE(bare_view.seesTheFloorAt(bare_view.viewFromGround(under))) << camera.name;
    }
    // The floor behind each camera is hidden, so the view is cut to the part ahead of it.
    EXPECT_LT(view.size().area(), bare_view.size().area()) << camera.name;
    // Two metres ahead of the camera, on its heading, stays in the view and seen.
    const Eigen::Vector2d ahead = foot + 2.0 * heading;
    const cv::Point2f p = view.viewFromGround(ahead);
    EXPECT_TRUE(cv::Rect(cv::Point(0, 0), view.size()).contains(p)) << camera.name;
    EXPECT_TRUE(view.seesTheFloorAt(p)) << camera.name;
  }
}

// A floor view is set in metres on the floor: the same lens and mounting imaged at twice the
// resolution (every pixel length doubled) gives the same view, pixel for pixel, of the same
// ground, sampled at twice the raw coordinates; only the view's resolution sets its size.
TEST(GroundView, AViewDerivesFromTheCalibrationNotItsPixelCount) {
  // With the extents held in metres (no reach that follows the focal length), a camera of
  // twice the pixels sees the same ground in the same view pixels.
  GroundViewOptions metres;
  metres.reference_focal_px = 0.0;
  for (const auto& camera : geometry::defaultRig().cameras) {
    geometry::RigCamera twice = camera;
    twice.model = testing::scaledCamera(camera.model, 2);
    const GroundView view(camera, metres), view_twice(twice, metres);
    ASSERT_EQ(view.size(), view_twice.size()) << camera.name;
    for (const cv::Point2f p : {cv::Point2f(0, 0), cv::Point2f(100.5f, 37), cv::Point2f(250, 190)}) {
      EXPECT_LT((view.groundFromView(p) - view_twice.groundFromView(p)).norm(), 1e-9);
      const auto raw = view.rawFromView(p), raw_twice = view_twice.rawFromView(p);
      ASSERT_EQ(raw.has_value(), raw_twice.has_value());
      if (!raw) continue;
      EXPECT_NEAR(raw_twice->x, (raw->x + 0.5f) * 2 - 0.5f, 1e-2) << camera.name;
      EXPECT_NEAR(raw_twice->y, (raw->y + 0.5f) * 2 - 0.5f, 1e-2) << camera.name;
    }
    // Half the metres per pixel: the same ground in twice the pixels a side (up to the 32 px
    // rounding of the view's sides and the crop's margin).
    GroundViewOptions fine = metres;
    fine.resolution = 0.0075;
    const GroundView view_fine(twice, fine);
    EXPECT_NEAR(view_fine.size().width, 2 * view.size().width, 96) << camera.name;
    EXPECT_NEAR(view_fine.size().height, 2 * view.size().height, 96) << camera.name;
  }
}

TEST(GroundView, AViewReachesFartherForACameraThatResolvesMore) {
  geometry::RigCamera camera = geometry::defaultRig().cameras[0];
  const GroundViewOptions options;  // far 6 m, half width 6 m at 365 px per radian
  EXPECT_DOUBLE_EQ(extentsFor(camera, options).far, options.far);  // the default rig's own
  camera.model.fx = 500.0;
  const GroundViewOptions longer = extentsFor(camera, options);
  EXPECT_NEAR(longer.far, 6.0 * 500.0 / 365.0, 1e-9);
  EXPECT_NEAR(longer.half_width, 6.0 * 500.0 / 365.0, 1e-9);
  EXPECT_DOUBLE_EQ(longer.near, options.near);  // the floor beside the camera stays
  EXPECT_GT(GroundView(camera, options).size().area(), GroundView(camera, GroundViewOptions{
      options.resolution, options.near, options.far, options.half_width, 0.0}).size().area());
  camera.model.fx = 3000.0;
  EXPECT_NEAR(extentsFor(camera, options).far, 6.0 * options.max_extent_scale, 1e-9);
  camera.model.fx = 250.0;  // a camera that resolves less looks less far
  EXPECT_NEAR(extentsFor(camera, options).far, 6.0 * 250.0 / 365.0, 1e-9);
  GroundViewOptions as_given = options;
  as_given.reference_focal_px = 0.0;
  EXPECT_DOUBLE_EQ(extentsFor(camera, as_given).far, options.far);
}

}  // namespace
}  // namespace parkloc::ocr
