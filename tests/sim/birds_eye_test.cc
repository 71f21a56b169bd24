// The stitched top-down image: a known ground point lands on its expected pixel, and the
// labels are the landmarks' corners through the pose into the image.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "sim/annotate.h"
#include "sim/birds_eye.h"
#include "sim/garage_builder.h"
#include "sim_test_util.h"

namespace parkloc::sim {
namespace {

TEST(BirdsEye, PixelAndGroundPointAreInverse) {
  const BirdsEyeStitcher stitcher(testing::scaledRig(0.25));
  EXPECT_EQ(stitcher.size(), cv::Size(560, 560));
  for (double x = -4.0; x <= 7.0; x += 1.1)
    for (double y = -5.5; y <= 5.5; y += 1.3) {
      const Eigen::Vector2d xy(x, y);
      EXPECT_LT((stitcher.vehicleFromPixel(stitcher.pixelFromVehicle(xy)) - xy).norm(), 1e-9);
    }
  // Forward is up, left is left: the rear axle's centre sits ahead_m down from the top.
  const Eigen::Vector2d origin = stitcher.pixelFromVehicle({0.0, 0.0});
  EXPECT_NEAR(origin.x(), 279.5, 1e-9);
  EXPECT_NEAR(origin.y(), 7.0 / 0.02 - 0.5, 1e-9);
  EXPECT_LT(stitcher.pixelFromVehicle({1.0, 1.0}).x(), origin.x());
  EXPECT_LT(stitcher.pixelFromVehicle({1.0, 0.0}).y(), origin.y());
  // Under the car no camera shows the floor.
  EXPECT_EQ(stitcher.cameraAt(stitcher.pixelFromVehicle({1.4, 0.0})), -1);
}

TEST(BirdsEye, AGroundMarkLandsOnItsPixel) {
  Garage g = testing::emptyGarage();
  const geometry::Rig rig = testing::scaledRig(0.5);
  const BirdsEyeStitcher stitcher(rig);
  const geometry::Pose2 pose(8.0, 9.0, 0.4);
  const geometry::Rigid3 vehicle_from_map = pose.toRigid3().inverse();
  // White squares, 20 cm, beside, ahead of and behind the car.
  const std::vector<Eigen::Vector3d> marks = {pose.toRigid3() * Eigen::Vector3d(1.5, 2.6, 0.0),
                                              pose.toRigid3() * Eigen::Vector3d(5.0, -1.0, 0.0),
                                              pose.toRigid3() * Eigen::Vector3d(-2.5, 0.8, 0.0),
                                              pose.toRigid3() * Eigen::Vector3d(0.3, -3.0, 0.0)};
  for (const auto& m : marks)
    g.levels[0].floor_decals.push_back(
        detail::Builder::solidDecal(m, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 0.2, 0.2,
                                    Eigen::Vector3f(1.0f, 1.0f, 1.0f)));
  const Renderer renderer(g, 0, rig, testing::raysOf(rig), testing::flatLight());
  cv::Mat avm, grey;
  avm = stitcher.stitch(renderer.render(pose, 3));
  cv::cvtColor(avm, grey, cv::COLOR_BGR2GRAY);
  for (const auto& m : marks) {
    const Eigen::Vector2d px = stitcher.pixelFromVehicle((vehicle_from_map * m).head<2>());
    const cv::Point at(static_cast<int>(std::lround(px.x())),
                       static_cast<int>(std::lround(px.y())));
    ASSERT_GE(stitcher.cameraAt(px), 0);
    // The mark (10 px across) is bright at its centre, the floor 25 px (0.5 m) away is not.
    const int mark = grey.at<uint8_t>(at);
    const int floor = grey.at<uint8_t>(at + cv::Point(25, 0));
    EXPECT_GT(mark, floor + 40) << px.transpose();
    // And its brightest pixels are centred on the expected pixel within a pixel.
    cv::Mat patch = grey(cv::Rect(at - cv::Point(12, 12), cv::Size(25, 25))) > (mark + floor) / 2;
    const cv::Moments mo = cv::moments(patch, true);
    ASSERT_GT(mo.m00, 20.0);
    EXPECT_NEAR(mo.m10 / mo.m00 - 12.0, px.x() - at.x, 1.0);
    EXPECT_NEAR(mo.m01 / mo.m00 - 12.0, px.y() - at.y, 1.0);
  }
}

TEST(BirdsEye, LabelsAreTheFloorTextsThroughThePose) {
  GarageSpec spec = testing::smallSpec();
  const Garage g = generateGarage(spec, 5);
  const geometry::Rig rig = testing::scaledRig(0.5);
  const BirdsEyeStitcher stitcher(rig);
  const geometry::Pose2 pose(14.0, g.aisle_y[0] + 0.3, 0.1);
  std::vector<io::ImageLabels> cameras;
  for (const auto& cam : rig.cameras) {
    io::ImageLabels l;
    l.instances = annotateImage(g, 0, cam, pose);
    cameras.push_back(l);
  }
  const io::ImageLabels avm = birdsEyeLabels(g, 0, stitcher, pose, cameras);
  EXPECT_EQ(avm.width, 560);
  int numbers = 0, cut = 0;
  const geometry::Rigid3 vehicle_from_map = pose.toRigid3().inverse();
  for (const io::LabelInstance& l : avm.instances) {
    bool outside = false;
    for (const auto& p : l.polygon)
      outside = outside || p.x() < 0.0 || p.y() < 0.0 || p.x() > avm.width - 1.0 ||
                p.y() > avm.height - 1.0;
    if (outside) {
      // A number the image's border cuts is don't care.
      EXPECT_FALSE(l.legible) << l.text;
      EXPECT_TRUE(l.truncated) << l.text;
      ++cut;
    }
    if (!l.legible) continue;
    ++numbers;
    for (const TextItem& item : g.levels[0].texts)
      if (item.landmark.id == l.landmark_id) {
        const auto corners = item.landmark.corners();
        for (int k = 0; k < 4; ++k)
          EXPECT_LT(
              (l.polygon[k] - stitcher.pixelFromVehicle((vehicle_from_map * corners[k]).head<2>()))
                  .norm(),
              1e-9);
        EXPECT_EQ(item.landmark.surface, map::Surface::kGround);
      }
    for (const auto& p : l.polygon) {
      EXPECT_GE(p.x(), 0.0);
      EXPECT_LE(p.x(), avm.width - 1.0);
    }
  }
  EXPECT_GE(numbers, 4);
  EXPECT_GE(cut, 1);
}

}  // namespace
}  // namespace parkloc::sim
