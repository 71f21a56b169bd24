// The same seed gives identical garages, images, labels, drives and odometry; another seed
// gives different ones.
#include <gtest/gtest.h>

#include "sim/annotate.h"
#include "sim/drive.h"
#include "sim_test_util.h"

namespace parkloc::sim {
namespace {

TEST(Determinism, SameSeedSameOutput) {
  const geometry::Rig rig = testing::scaledRig(0.25);
  const auto rays = testing::raysOf(rig);
  GarageSpec spec = testing::smallSpec();
  spec.occupancy = 0.5;
  spec.worn_share = 0.5;
  const Garage a = generateGarage(spec, 42), b = generateGarage(spec, 42),
               c = generateGarage(spec, 43);
  ASSERT_EQ(a.map.size(), b.map.size());
  for (size_t i = 0; i < a.map.size(); ++i) {
    EXPECT_EQ(a.map.landmarks()[i].text, b.map.landmarks()[i].text);
    EXPECT_EQ(a.map.landmarks()[i].position, b.map.landmarks()[i].position);
    EXPECT_EQ(a.map.landmarks()[i].width, b.map.landmarks()[i].width);
  }
  const DriveSpec drive_spec{"tour", "weak", "", 6.0};
  const Drive da = planDrive(a, 0, drive_spec, 7), db = planDrive(b, 0, drive_spec, 7);
  ASSERT_EQ(da.states().size(), db.states().size());
  const auto oa = simulateOdometry(da, 50.0, 9), ob = simulateOdometry(db, 50.0, 9);
  ASSERT_EQ(oa.size(), ob.size());
  for (size_t i = 0; i < oa.size(); ++i) {
    EXPECT_EQ(oa[i].speed, ob[i].speed);
    EXPECT_EQ(oa[i].yaw_rate, ob[i].yaw_rate);
  }
  const LightingOptions light = lightingForCondition("weak", 3);
  const Renderer ra(a, 0, rig, rays, light), rb(b, 0, rig, rays, light), rc(c, 0, rig, rays, light);
  const geometry::Pose2 pose = da.at(3.0).pose;
  bool any_difference_to_other_seed = false;
  for (size_t ci = 0; ci < rig.cameras.size(); ++ci) {
    const cv::Mat ia = ra.renderCamera(ci, pose, 5), ib = rb.renderCamera(ci, pose, 5);
    EXPECT_EQ(cv::norm(ia, ib, cv::NORM_INF), 0.0) << rig.cameras[ci].name;
    any_difference_to_other_seed |= cv::norm(ia, rc.renderCamera(ci, pose, 5), cv::NORM_INF) > 0.0;
    const auto la = annotateImage(a, 0, rig.cameras[ci], pose),
               lb = annotateImage(b, 0, rig.cameras[ci], pose);
    ASSERT_EQ(la.size(), lb.size());
    for (size_t k = 0; k < la.size(); ++k) {
      EXPECT_EQ(la[k].landmark_id, lb[k].landmark_id);
      EXPECT_EQ(la[k].occluded_fraction, lb[k].occluded_fraction);
      for (int j = 0; j < 4; ++j) EXPECT_EQ(la[k].polygon[j], lb[k].polygon[j]);
    }
  }
  EXPECT_TRUE(any_difference_to_other_seed);
  // The noise seed changes the image (sensor noise), not the scene.
  EXPECT_GT(cv::norm(ra.renderCamera(0, pose, 5), ra.renderCamera(0, pose, 6), cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace parkloc::sim
