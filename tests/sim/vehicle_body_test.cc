// The recording car's own body (geometry::RigCamera::body) in the simulator: the labels count
// what it hides as occluded, and the renderer draws it where the hidden text would have been.
#include <gtest/gtest.h>

#include "sim/annotate.h"
#include "sim_test_util.h"

namespace parkloc::sim {
namespace {

TEST(VehicleBodyInTheSimulator, TextsBehindTheCarAreHiddenInTheLabelsAndTheImage) {
  const geometry::Rig rig = testing::scaledRig(0.5);
  const Garage g = generateGarage(testing::smallSpec(), 5);
  const geometry::Pose2 pose(14.0, g.aisle_y[0] + 0.5, 0.0);
  const geometry::Rigid3 vehicle_from_map = pose.toRigid3().inverse();
  ASSERT_TRUE(rig.cameras.front().body);
  const geometry::VehicleBody body = *rig.cameras.front().body;
  geometry::Rig bare_rig = rig;
  for (auto& camera : bare_rig.cameras) camera.body.reset();
  const auto rays = testing::raysOf(rig);
  const Renderer renderer(g, 0, rig, rays, testing::flatLight());
  const Renderer bare_renderer(g, 0, bare_rig, rays, testing::flatLight());
  int hidden = 0, unchanged = 0;
  for (size_t c = 0; c < rig.cameras.size(); ++c) {
    const geometry::RigCamera& camera = rig.cameras[c];
    const auto bare = annotateImage(g, 0, bare_rig.cameras[c], pose);
    const auto masked = annotateImage(g, 0, camera, pose);
    ASSERT_EQ(bare.size(), masked.size());
    const cv::Mat img = renderer.renderCamera(c, pose, 1);
    const cv::Mat bare_img = bare_renderer.renderCamera(c, pose, 1);
    for (size_t i = 0; i < bare.size(); ++i) {
      if (bare[i].occluded_fraction > 0.0) continue;
      const map::Landmark* lm = g.map.findById(bare[i].landmark_id);
      ASSERT_NE(lm, nullptr);
      const Eigen::Vector3d centre = vehicle_from_map * lm->position;
      if (!geometry::bodyBlocks(body, camera.vehicle_from_camera.translation(), centre)) {
        unchanged += masked[i].occluded_fraction == 0.0;
        continue;
      }
      // The car stands between the camera and the text's centre: the label says hidden in
      // part, and the image shows the car's body there instead of the floor or the pillar.
      ++hidden;
      EXPECT_GT(masked[i].occluded_fraction, 0.0) << lm->text << " in " << camera.name;
      const auto px = camera.model.project(camera.vehicle_from_camera.inverse() * centre);
      ASSERT_TRUE(px);
      const cv::Point at(cvRound(px->x()), cvRound(px->y()));
      if (at.inside(cv::Rect(0, 0, img.cols, img.rows))) {
        EXPECT_NE(img.at<cv::Vec3b>(at), bare_img.at<cv::Vec3b>(at)) << lm->text;
      }
    }
  }
  EXPECT_GT(hidden, 0);
  EXPECT_GT(unchanged, 0);
}

}  // namespace
}  // namespace parkloc::sim
