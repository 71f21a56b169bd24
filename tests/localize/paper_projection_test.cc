#include "localize/paper_projection.h"

#include <gtest/gtest.h>

#include "geometry/rig.h"
#include "synthetic_scene.h"

namespace parkloc::localize {
namespace {

PaperObservation observation(const std::string& id, Eigen::Vector2d map, Eigen::Vector2d rel,
                             int camera) {
  PaperObservation o;
  o.landmark_id = id;
  o.map_position = map;
  o.relative = rel;
  o.camera = camera;
  return o;
}

TEST(PaperProjection, TextCentreOfPolygonAndBox) {
  const std::array<Eigen::Vector2d, 4> q{Eigen::Vector2d(0, 0), Eigen::Vector2d(4, 0),
                                         Eigen::Vector2d(4, 2), Eigen::Vector2d(0, 4)};
  EXPECT_TRUE(textCentre(q, true).isApprox(Eigen::Vector2d(2.0, 1.5)));
  EXPECT_TRUE(textCentre(q, false).isApprox(Eigen::Vector2d(2.0, 2.0)));
}

TEST(PaperProjection, McrpAveragesCamerasAndMcapAveragesLandmarks) {
  // Landmark A seen by two cameras (relative x 2 and 4 -> vehicle at 10-2 or 10-4), B by one.
  const std::vector<PaperObservation> obs{observation("A", {10, 0}, {2, 0}, 0),
                                          observation("A", {10, 0}, {4, 0}, 1),
                                          observation("B", {20, 5}, {11, 5}, 2)};
  const auto both = paperFuse(obs, 0.0, true, true);
  ASSERT_TRUE(both);
  // A: relative 3 -> 7; B: 9; mean 8.
  EXPECT_NEAR(both->position.x(), 8.0, 1e-12);
  EXPECT_NEAR(both->position.y(), 0.0, 1e-12);
  EXPECT_EQ(both->landmarks, 2);
  EXPECT_EQ(both->observations, 3);
  // Without MCRP, A uses its first camera only: 8 and 9 -> 8.5.
  EXPECT_NEAR(paperFuse(obs, 0.0, false, true)->position.x(), 8.5, 1e-12);
  // Without MCAP only the nearest landmark (A, relative 3 m) counts: 7.
  EXPECT_NEAR(paperFuse(obs, 0.0, true, false)->position.x(), 7.0, 1e-12);
  // Heading rotates the relative offsets: yaw 90 degrees, A alone -> (10, -3).
  const auto turned = paperFuse({obs[0], obs[1]}, M_PI / 2, true, true);
  EXPECT_NEAR(turned->position.x(), 10.0, 1e-12);
  EXPECT_NEAR(turned->position.y(), -3.0, 1e-12);
  EXPECT_FALSE(paperFuse({}, 0.0, true, true));
}

TEST(PaperProjection, HomographyOfTheTextGivesItsPositionAndHeading) {
  const auto rig = geometry::defaultRig();
  const auto map = testing::aisleMap();
  const geometry::Pose2 truth(6.0, 0.4, 0.2);
  int checked = 0;
  for (const auto& camera : rig.cameras) {
    const auto homography = geometry::GroundHomography::fromCamera(camera);
    testing::SpotOptions spot;
    spot.pillars = false;
    spot.max_range_m = 6.0;
    for (const auto& t : testing::spotExactly(camera, map, truth, spot)) {
      std::array<Eigen::Vector2d, 4> q;
      for (int i = 0; i < 4; ++i) q[i] = {t.polygon[i].x, t.polygon[i].y};
      auto o = paperObserve(homography, camera.model, q, true);
      if (!o) continue;  // beyond 90 degrees off-axis: no undistorted view there
      const auto* l = map.findByText(t.text).front();
      const Eigen::Vector2d expected = truth.inverse() * l->position.head<2>();
      // The mean of the distorted corners is not the image of the centre: a few cm.
      EXPECT_LT((o->relative - expected).norm(), 0.1) << t.text << " " << camera.name;
      ASSERT_TRUE(o->reading_angle);
      o->map_heading = l->heading;
      const auto yaw = headingFromTextDirections({*o});
      EXPECT_NEAR(geometry::wrapAngle(*yaw - truth.yaw), 0.0, 3.0 * M_PI / 180);
      ++checked;
    }
  }
  EXPECT_GT(checked, 2);
}

}  // namespace
}  // namespace parkloc::localize
