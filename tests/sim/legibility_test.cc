// Text too thin in the image to be read is labelled "not legible" (ICDAR's don't care), not
// left out: a detector that still finds it is then neither rewarded nor counted wrong.
#include <gtest/gtest.h>

#include "sim/annotate.h"
#include "sim_test_util.h"

namespace parkloc::sim {
namespace {

double apparentHeight(const io::LabelInstance& l) {
  const auto& p = l.polygon;
  const Eigen::Vector2d d1 = p[2] - p[0], d2 = p[3] - p[1];
  const double area = 0.5 * std::abs(d1.x() * d2.y() - d1.y() * d2.x());
  const double length = 0.5 * ((p[1] - p[0]).norm() + (p[2] - p[3]).norm());
  return area / length;
}

TEST(Legibility, FollowsTheApparentHeightOfTheText) {
  const geometry::Rig rig = geometry::defaultRig();
  const Garage g = generateGarage(testing::smallSpec(), 5);
  const geometry::Pose2 pose(14.0, g.aisle_y[0] + 0.5, 0.0);
  AnnotateOptions options;
  int legible = 0, illegible = 0;
  for (const auto& camera : rig.cameras)
    for (const auto& l : annotateImage(g, 0, camera, pose, options)) {
      const double h = apparentHeight(l);
      EXPECT_GE(h, options.min_labelled_height_px - 1e-9) << l.text;
      EXPECT_EQ(l.legible, h >= options.min_height_px) << l.text << " " << h;
      (l.legible ? legible : illegible)++;
    }
  EXPECT_GT(legible, 0);
  EXPECT_GT(illegible, 0);  // far numbers along the aisle, seen edge-on
}

}  // namespace
}  // namespace parkloc::sim
