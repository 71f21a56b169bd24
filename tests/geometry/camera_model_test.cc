#include "geometry/camera_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/calib3d.hpp>
#include <random>

#include "geometry/rig.h"

namespace parkloc::geometry {
namespace {

CameraModel pinholeCamera() {
  CameraModel m;
  m.type = CameraModelType::kPinhole;
  m.width = 1280;
  m.height = 800;
  m.fx = 700.0;
  m.fy = 690.0;
  m.cx = 641.0;
  m.cy = 398.0;
  m.distortion = {-0.12, 0.03, 0.0008, -0.0005};
  return m;
}

// The property suite runs over every camera model (STYLE.md: one suite per interface).
class CameraModelRoundTrip : public ::testing::TestWithParam<CameraModel> {};

TEST_P(CameraModelRoundTrip, UnprojectThenProjectReturnsThePixelOverTheWholeImage) {
  const CameraModel m = GetParam();
  int checked = 0;
  for (double v = 0.0; v < m.height; v += 8.0) {
    for (double u = 0.0; u < m.width; u += 8.0) {
      const Eigen::Vector2d pixel(u, v);
      const auto ray = m.unproject(pixel);
      if (!ray) continue;  // outside the fisheye image circle's valid domain
      EXPECT_NEAR(ray->norm(), 1.0, 1e-12);
      for (const double depth : {0.3, 2.0, 25.0}) {
        const auto back = m.project(depth * *ray);
        ASSERT_TRUE(back.has_value()) << "pixel " << u << "," << v;
        ASSERT_LT((*back - pixel).norm(), 1e-6) << "pixel " << u << "," << v;
      }
      ++checked;
    }
  }
  // Every pixel of both cameras maps: the fisheye's field of view covers the whole image.
  const int all = ((m.height + 7) / 8) * ((m.width + 7) / 8);
  EXPECT_EQ(checked, all);
}

TEST_P(CameraModelRoundTrip, ProjectThenUnprojectReturnsTheDirection) {
  const CameraModel m = GetParam();
  const double max_angle = m.type == CameraModelType::kFisheye ? m.max_theta - 1e-3 : 0.6;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(0.0, max_angle), azimuth(-M_PI, M_PI);
  for (int i = 0; i < 2000; ++i) {
    const double theta = angle(rng), phi = azimuth(rng);
    const Eigen::Vector3d dir(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                              std::cos(theta));
    const auto pixel = m.project(3.0 * dir);
    ASSERT_TRUE(pixel.has_value());
    const auto ray = m.unproject(*pixel);
    ASSERT_TRUE(ray.has_value());
    EXPECT_LT((*ray - dir).norm(), 1e-9) << "theta " << theta;
  }
}

INSTANTIATE_TEST_SUITE_P(Models, CameraModelRoundTrip,
                         ::testing::Values(defaultRig().cameras[0].model, pinholeCamera()),
                         [](const auto& info) { return toString(info.param.type); });

TEST(FisheyeCamera, ReachesPastNinetyDegreesAndRejectsBeyondItsFieldOfView) {
  const CameraModel m = defaultRig().cameras[0].model;
  const double behind = 95.0 * M_PI / 180.0;
  const auto pixel = m.project({std::sin(behind), 0.0, std::cos(behind)});
  ASSERT_TRUE(pixel.has_value());
  EXPECT_GT(pixel->x(), m.cx + 500.0);
  EXPECT_FALSE(m.project({0.0, 0.0, -1.0}).has_value());
  EXPECT_FALSE(m.project({1.0, 0.0, -1.0}).has_value());  // 135 degrees off axis
}

TEST(PinholeCamera, RejectsPointsBehindTheCamera) {
  EXPECT_FALSE(pinholeCamera().project({0.1, 0.2, -1.0}).has_value());
}

TEST(FisheyeCamera, EqualsOpenCvFisheyeProjectPoints) {
  const CameraModel m = defaultRig().cameras[0].model;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> xy(-2.0, 2.0), z(0.2, 5.0);
  std::vector<cv::Point3d> points;
  for (int i = 0; i < 500; ++i) points.emplace_back(xy(rng), xy(rng), z(rng));
  const cv::Matx33d K(m.fx, 0, m.cx, 0, m.fy, m.cy, 0, 0, 1);
  const cv::Vec4d D(m.distortion[0], m.distortion[1], m.distortion[2], m.distortion[3]);
  std::vector<cv::Point2d> expected;
  cv::fisheye::projectPoints(points, expected, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), K, D);
  for (size_t i = 0; i < points.size(); ++i) {
    const auto p = m.project({points[i].x, points[i].y, points[i].z});
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(p->x(), expected[i].x, 1e-6);
    EXPECT_NEAR(p->y(), expected[i].y, 1e-6);
  }
}

TEST(PinholeCamera, EqualsOpenCvProjectPoints) {
  const CameraModel m = pinholeCamera();
  std::vector<cv::Point3d> points;
  for (double x = -1.0; x <= 1.0; x += 0.25)
    for (double y = -0.6; y <= 0.6; y += 0.2) points.emplace_back(x, y, 2.5);
  const cv::Matx33d K(m.fx, 0, m.cx, 0, m.fy, m.cy, 0, 0, 1);
  const std::vector<double> D{m.distortion[0], m.distortion[1], m.distortion[2], m.distortion[3]};
  std::vector<cv::Point2d> expected;
  cv::projectPoints(points, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), K, D, expected);
  for (size_t i = 0; i < points.size(); ++i) {
    const auto p = m.project({points[i].x, points[i].y, points[i].z});
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(p->x(), expected[i].x, 1e-6);
    EXPECT_NEAR(p->y(), expected[i].y, 1e-6);
  }
}

}  // namespace
}  // namespace parkloc::geometry
