// The vehicle's body hides the floor under and beside it from the cameras on its skin, and
// nothing outside it.
#include "geometry/vehicle_body.h"

#include <gtest/gtest.h>

#include "geometry/rig.h"

namespace parkloc::geometry {
namespace {

VehicleBody defaultBody() {
  const Rig rig = defaultRig();
  EXPECT_TRUE(rig.cameras.front().body);
  return *rig.cameras.front().body;
}

TEST(VehicleBody, ACameraOnTheBumperSeesOutwardsButNotThroughTheCar) {
  const VehicleBody body = defaultBody();
  const Eigen::Vector3d front_camera =
      defaultRig().find("front")->vehicle_from_camera.translation();
  EXPECT_FALSE(bodyBlocks(body, front_camera, {6.0, 0.0, 0.0}));
  EXPECT_FALSE(bodyBlocks(body, front_camera, {4.0, 3.0, 0.0}));
  // Beside the car behind the bumper, and under the car.
  EXPECT_TRUE(bodyBlocks(body, front_camera, {2.5, 2.5, 0.0}));
  EXPECT_TRUE(bodyBlocks(body, front_camera, {1.0, 0.0, 0.0}));
}

TEST(VehicleBody, AMirrorCameraSeesBesideTheCarButNotUnderIt) {
  const VehicleBody body = defaultBody();
  const Eigen::Vector3d left_camera = defaultRig().find("left")->vehicle_from_camera.translation();
  EXPECT_FALSE(bodyBlocks(body, left_camera, {-0.5, 2.0, 0.0}));
  EXPECT_FALSE(bodyHitsRay(body, left_camera, {0.0, 0.0, -1.0}));  // straight down
  EXPECT_TRUE(bodyBlocks(body, left_camera, {2.0, 0.0, 0.0}));
  EXPECT_TRUE(bodyBlocks(body, left_camera, {2.0, -2.5, 0.0}));  // the other side
  EXPECT_TRUE(bodyHitsRay(body, left_camera, {0.0, -1.0, -0.2}));
}

TEST(VehicleBody, ASegmentThatStopsShortOrPassesAboveIsFree) {
  const VehicleBody body = defaultBody();
  EXPECT_FALSE(bodyBlocks(body, {2.0, 3.0, 1.0}, {2.0, 2.0, 1.0}));
  EXPECT_FALSE(bodyBlocks(body, {-3.0, 0.0, 1.6}, {6.0, 0.0, 1.6}));
  EXPECT_TRUE(bodyBlocks(body, {-3.0, 0.0, 1.4}, {6.0, 0.0, 1.4}));
  // Along a face, on the skin: not inside.
  EXPECT_FALSE(bodyBlocks(body, {3.7, -3.0, 0.6}, {3.7, 3.0, 0.6}));
}

}  // namespace
}  // namespace parkloc::geometry
