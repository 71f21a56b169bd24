// A text cut by the image's edge is labelled with the part the image shows.
#include <gtest/gtest.h>

#include "geometry/text_polygon.h"
#include "sim/annotate.h"
#include "sim_test_util.h"

namespace parkloc::sim {
namespace {

Eigen::Vector2d centreOf(const geometry::TextPolygon& polygon) {
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (const auto& p : polygon) c += 0.25 * p;
  return c;
}

TEST(Truncation, ATextCutByTheImageEdgeCarriesThePartThatShows) {
  const geometry::Rig rig = testing::scaledRig(0.5);
  const Garage g = generateGarage(testing::smallSpec(), 5);
  int cut = 0;
  // Along the aisle, every camera: the numbers slide past the images' edges.
  for (double x = 6.0; x <= 30.0; x += 1.5) {
    const geometry::Pose2 pose(x, g.aisle_y[0] + 0.5, 0.0);
    for (const auto& camera : rig.cameras)
      for (const auto& l : annotateImage(g, 0, camera, pose)) {
        if (!l.truncated) {
          if (l.occluded_fraction == 0.0) {
            EXPECT_FALSE(l.visible_polygon) << l.landmark_id << " is whole in " << camera.name;
          }
          continue;
        }
        if (!l.visible_polygon) continue;  // too little of it seen
        ++cut;
        // Its middle is in the image, and it is part of the text: no longer than the whole
        // (within a pixel: the lens bends the two quads' straight edges differently).
        EXPECT_TRUE(camera.model.inImage(centreOf(*l.visible_polygon)))
            << l.landmark_id << " in " << camera.name;
        EXPECT_LE(geometry::readingLengthPx(*l.visible_polygon),
                  geometry::readingLengthPx(l.polygon) + 1.0);
      }
  }
  EXPECT_GT(cut, 5);
}

}  // namespace
}  // namespace parkloc::sim
