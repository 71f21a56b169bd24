#include "localize/roi_prediction.h"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "synthetic_scene.h"

namespace parkloc::localize {
namespace {

TEST(ReadingAlignedBox, HoldsTheQuadGrownByTheMargin) {
  // Upright text: top edge at y = 0 (image y grows downwards).
  const std::array<Eigen::Vector2d, 4> upright{Eigen::Vector2d(0, 0), Eigen::Vector2d(10, 0),
                                               Eigen::Vector2d(10, 4), Eigen::Vector2d(0, 4)};
  const auto box = readingAlignedBox(upright, 2.0);
  EXPECT_TRUE(box[0].isApprox(Eigen::Vector2d(-2, -2)));
  EXPECT_TRUE(box[1].isApprox(Eigen::Vector2d(12, -2)));
  EXPECT_TRUE(box[2].isApprox(Eigen::Vector2d(12, 6)));
  EXPECT_TRUE(box[3].isApprox(Eigen::Vector2d(-2, 6)));
  // Upside-down text keeps its reading order: top-left is now at the bottom right.
  const std::array<Eigen::Vector2d, 4> flipped{upright[2], upright[3], upright[0], upright[1]};
  const auto turned = readingAlignedBox(flipped, 0.0);
  EXPECT_TRUE(turned[0].isApprox(Eigen::Vector2d(10, 4)));
  // A folded, almost flat quad still gives a box that holds every corner.
  const std::array<Eigen::Vector2d, 4> folded{Eigen::Vector2d(493, 248), Eigen::Vector2d(522, 246),
                                              Eigen::Vector2d(516, 247), Eigen::Vector2d(487, 250)};
  const auto held = readingAlignedBox(folded, 1.0);
  std::vector<cv::Point2f> polygon;
  for (const auto& p : held) polygon.emplace_back(p.x(), p.y());
  for (const auto& p : folded)
    EXPECT_GT(cv::pointPolygonTest(polygon, cv::Point2f(p.x(), p.y()), true), 0.5);
}

TEST(RoiPrediction, RegionsContainTheTextSeenFromAPerturbedPose) {
  const auto rig = geometry::defaultRig();
  const auto map = testing::aisleMap();
  const FloorHeights floors(map);
  const geometry::Pose2 truth(8.0, 0.3, 0.1);
  // The prediction is off by about one sigma.
  const geometry::Pose2 predicted(8.1, 0.25, 0.1 + 0.01);
  const Eigen::Matrix3d covariance = Eigen::Vector3d(0.01, 0.01, 1e-4).asDiagonal();
  const auto nearby = map.withinRadius(predicted.translation(), 12.0);
  int contained = 0, total = 0;
  for (const auto& camera : rig.cameras) {
    const auto regions = predictRegions(camera, nearby, floors, predicted, covariance);
    for (const auto& t : testing::spotExactly(camera, map, truth)) {
      const ocr::RegionOfInterest* match = nullptr;
      for (const auto& r : regions)
        if (r.expected_texts.front() == t.text) match = &r;
      if (!match) continue;  // a text the prediction deems too small
      ++total;
      std::vector<cv::Point2f> polygon(match->polygon.begin(), match->polygon.end());
      bool inside = true;
      for (const auto& p : t.polygon)
        inside = inside && cv::pointPolygonTest(polygon, p, false) >= 0;
      contained += inside;
    }
    for (const auto& r : regions) EXPECT_EQ(r.expected_texts.size(), 1u);
  }
  EXPECT_GT(total, 5);
  EXPECT_EQ(contained, total);
}

TEST(RoiPrediction, SkipsTextBehindTheCameraAndTinyText) {
  const auto rig = geometry::defaultRig();
  const auto map = testing::aisleMap();
  const FloorHeights floors(map);
  const geometry::Pose2 pose(8.0, 0.0, 0.0);
  const auto& front = rig.cameras[0];
  // Only landmarks far behind the vehicle: the front camera sees none of them.
  std::vector<const map::Landmark*> behind;
  for (const auto* l : map.withinRadius(pose.translation(), 40.0))
    if (l->position.x() < -10.0) behind.push_back(l);
  ASSERT_FALSE(behind.empty());
  EXPECT_TRUE(
      predictRegions(front, behind, floors, pose, Eigen::Matrix3d::Identity() * 1e-4).empty());
  RoiOptions huge_minimum;
  huge_minimum.min_size_px = 5000.0;
  EXPECT_TRUE(predictRegions(front, map.withinRadius(pose.translation(), 12.0), floors, pose,
                             Eigen::Matrix3d::Identity() * 1e-4, huge_minimum)
                  .empty());
}

}  // namespace
}  // namespace parkloc::localize
