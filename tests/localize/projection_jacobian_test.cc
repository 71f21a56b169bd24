#include "localize/projection_jacobian.h"

#include <gtest/gtest.h>

#include <random>

#include "geometry/rig.h"
#include "localize/pose_solver.h"

namespace parkloc::localize {
namespace {

Eigen::Matrix<double, 2, 3> numericJacobian(const geometry::CameraModel& model,
                                            const Eigen::Vector3d& p) {
  Eigen::Matrix<double, 2, 3> J;
  const double h = 1e-6;
  for (int c = 0; c < 3; ++c) {
    Eigen::Vector3d d = Eigen::Vector3d::Zero();
    d[c] = h;
    J.col(c) = (*model.project(p + d) - *model.project(p - d)) / (2 * h);
  }
  return J;
}

void checkModel(const geometry::CameraModel& model, std::mt19937& rng, bool wide) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0;
  for (int i = 0; i < 300; ++i) {
    // Points all around, also past 90 degrees for the fisheye.
    Eigen::Vector3d p(u(rng) * 3.0, u(rng) * 3.0, wide ? u(rng) * 3.0 : 0.5 + std::abs(u(rng)) * 3);
    const auto reference = model.project(p);
    const auto ours = projectWithJacobian(model, p);
    ASSERT_EQ(reference.has_value(), ours.has_value());
    if (!ours) continue;
    EXPECT_LT((ours->pixel - *reference).norm(), 1e-9);
    const auto numeric = numericJacobian(model, p);
    EXPECT_LT((ours->J_pixel_point - numeric).norm(), 1e-5 * (1.0 + numeric.norm()))
        << "at " << p.transpose();
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

TEST(ProjectionJacobian, FisheyeMatchesCameraModelAndCentralDifferences) {
  std::mt19937 rng(7);
  checkModel(geometry::defaultRig().cameras[0].model, rng, true);
}

TEST(ProjectionJacobian, PinholeMatchesCameraModelAndCentralDifferences) {
  geometry::CameraModel pinhole;
  pinhole.type = geometry::CameraModelType::kPinhole;
  pinhole.width = 1280;
  pinhole.height = 800;
  pinhole.fx = 600;
  pinhole.fy = 590;
  pinhole.cx = 640;
  pinhole.cy = 400;
  pinhole.distortion = {-0.2, 0.05, 0.001, -0.002};
  std::mt19937 rng(8);
  checkModel(pinhole, rng, false);
}

TEST(ProjectionJacobian, OnTheFisheyeAxis) {
  const auto model = geometry::defaultRig().cameras[0].model;
  const auto ours = projectWithJacobian(model, {0.0, 0.0, 2.0});
  ASSERT_TRUE(ours);
  const auto numeric = numericJacobian(model, {0.0, 0.0, 2.0});
  EXPECT_LT((ours->J_pixel_point - numeric).norm(), 1e-4);
}

TEST(CornerProjection, PoseJacobianMatchesCentralDifferences) {
  const auto rig = geometry::defaultRig();
  const geometry::Pose2 pose(3.0, -1.0, 0.4);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-6.0, 6.0);
  int checked = 0;
  for (int i = 0; i < 200; ++i) {
    const auto& camera = rig.cameras[i % 4];
    const Eigen::Vector3d corner(pose.x + u(rng), pose.y + u(rng), i % 3 == 0 ? 1.5 : 0.0);
    const auto p = projectMapCorner(camera, pose, corner);
    if (!p) continue;
    Eigen::Matrix<double, 2, 3> numeric;
    const double h = 1e-6;
    bool ok = true;
    for (int c = 0; c < 3 && ok; ++c) {
      Eigen::Vector3d d = Eigen::Vector3d::Zero();
      d[c] = h;
      const auto plus =
          projectMapCorner(camera, {pose.x + d.x(), pose.y + d.y(), pose.yaw + d.z()}, corner);
      const auto minus =
          projectMapCorner(camera, {pose.x - d.x(), pose.y - d.y(), pose.yaw - d.z()}, corner);
      ok = plus && minus;
      if (ok) numeric.col(c) = (plus->pixel - minus->pixel) / (2 * h);
    }
    if (!ok) continue;
    EXPECT_LT((p->J_pixel_pose - numeric).norm(), 1e-5 * (1.0 + numeric.norm()));
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

}  // namespace
}  // namespace parkloc::localize
