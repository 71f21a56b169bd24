#include "geometry/ground_projection.h"

#include <gtest/gtest.h>

#include <opencv2/calib3d.hpp>
#include <random>

#include "geometry/rig.h"

namespace parkloc::geometry {
namespace {

TEST(GroundProjection, HomographyAndRayIntersectionAgreeWithinAMillimetre) {
  const Rig rig = defaultRig();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coord(-10.0, 10.0);
  for (const RigCamera& camera : rig.cameras) {
    const GroundHomography H = GroundHomography::fromCamera(camera);
    const Rigid3 camera_from_vehicle = camera.vehicle_from_camera.inverse();
    int compared = 0;
    for (int i = 0; i < 4000 && compared < 300; ++i) {
      const Eigen::Vector3d ground(coord(rng), coord(rng), 0.0);
      const Eigen::Vector3d in_camera = camera_from_vehicle * ground;
      if (in_camera.z() < 0.05 || (ground - camera.vehicle_from_camera.translation()).norm() > 10.0)
        continue;
      const auto pixel = camera.model.project(in_camera);
      if (!pixel || !camera.model.inImage(*pixel)) continue;
      const auto by_ray = pixelToPlane(camera, *pixel, Plane::ground());
      const auto by_h = H.groundFromPixel(camera.model, *pixel);
      ASSERT_TRUE(by_ray.has_value());
      ASSERT_TRUE(by_h.has_value());
      EXPECT_LT((by_ray->head<2>() - ground.head<2>()).norm(), 1e-3);
      EXPECT_LT((*by_h - ground.head<2>()).norm(), 1e-3) << camera.name;
      ++compared;
    }
    EXPECT_GT(compared, 100) << camera.name;
  }
}

TEST(GroundProjection, HomographyEqualsOpenCvFindHomographyOnTheSamePoints) {
  const RigCamera camera = defaultRig().cameras[0];
  const GroundHomography H = GroundHomography::fromCamera(camera);
  std::vector<cv::Point2d> ground, image;
  for (double x = 4.5; x <= 9.0; x += 1.5)
    for (double y = -2.0; y <= 2.0; y += 1.0) {
      const Eigen::Vector3d p = H.undistorted_from_ground * Eigen::Vector3d(x, y, 1.0);
      ground.emplace_back(x, y);
      image.emplace_back(p.x() / p.z(), p.y() / p.z());
    }
  const cv::Mat cv_H = cv::findHomography(ground, image);
  const Eigen::Matrix3d ours = H.undistorted_from_ground / H.undistorted_from_ground(2, 2);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(ours(r, c), cv_H.at<double>(r, c), 1e-6 * std::max(1.0, std::abs(ours(r, c))));
}

TEST(GroundProjection, PixelsAboveTheHorizonDoNotReachTheGround) {
  const RigCamera camera = defaultRig().cameras[0];  // front, pitched down 20 degrees
  const GroundHomography H = GroundHomography::fromCamera(camera);
  const Eigen::Vector2d sky(camera.model.cx, 5.0);
  EXPECT_FALSE(pixelToPlane(camera, sky, Plane::ground()).has_value());
  EXPECT_FALSE(H.groundFromPixel(camera.model, sky).has_value());
}

TEST(GroundProjection, RayMeetsAVerticalPillarFace) {
  const RigCamera camera = defaultRig().cameras[2];  // left
  // A pillar face 3 m to the left of the vehicle, facing the vehicle (normal -y).
  const Plane face = Plane::throughPoint({0.0, -1.0, 0.0}, {0.0, 3.0, 0.0});
  const Eigen::Vector3d target(2.5, 3.0, 1.2);
  const auto pixel = camera.model.project(camera.vehicle_from_camera.inverse() * target);
  ASSERT_TRUE(pixel.has_value());
  const auto hit = pixelToPlane(camera, *pixel, face);
  ASSERT_TRUE(hit.has_value());
  EXPECT_LT((*hit - target).norm(), 1e-9);
}

TEST(Pose2, ComposeAndInverseAreConsistent) {
  const Pose2 a(1.0, -2.0, 0.7), b(-0.5, 3.0, -2.9);
  const Pose2 id = a * a.inverse();
  EXPECT_NEAR(id.x, 0.0, 1e-12);
  EXPECT_NEAR(id.y, 0.0, 1e-12);
  EXPECT_NEAR(id.yaw, 0.0, 1e-12);
  const Eigen::Vector2d p(0.3, 0.9);
  EXPECT_LT(((a * b) * p - a * (b * p)).norm(), 1e-12);
  EXPECT_NEAR((a * b).yaw, wrapAngle(0.7 - 2.9), 1e-12);
  const Pose2 back = Pose2::fromRigid3(a.toRigid3());
  EXPECT_NEAR(back.x, a.x, 1e-12);
  EXPECT_NEAR(back.yaw, a.yaw, 1e-12);
}

}  // namespace
}  // namespace parkloc::geometry
