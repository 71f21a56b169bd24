// A parking number hidden behind a car is flagged occluded, and the renderer draws the car
// where the label says the number is.
#include <gtest/gtest.h>

#include "sim/annotate.h"
#include "sim_test_util.h"

namespace parkloc::sim {
namespace {

const io::LabelInstance* findLabel(const std::vector<io::LabelInstance>& labels,
                                   const std::string& id) {
  for (const auto& l : labels)
    if (l.landmark_id == id) return &l;
  return nullptr;
}

TEST(Occlusion, NumberBehindACarIsFlagged) {
  const geometry::Rig rig = testing::scaledRig(0.5);
  Garage g = generateGarage(testing::smallSpec(), 5);
  GarageLevel& L = g.levels[0];
  // The right camera of a car driving east sees the numbers of the south row.
  const geometry::Pose2 pose(14.0, g.aisle_y[0] + 0.5, 0.0);
  const size_t right = 3;
  ASSERT_EQ(rig.cameras[right].name, "right");
  const auto before = annotateImage(g, 0, rig.cameras[right], pose);
  const io::LabelInstance* target = nullptr;
  for (const auto& l : before)
    if (l.cls == map::TextClass::kParkingNumber && !l.truncated && l.occluded_fraction == 0.0 &&
        (!target || std::abs(l.polygon[0].x() - 320) < std::abs(target->polygon[0].x() - 320)))
      target = &l;
  ASSERT_NE(target, nullptr);
  const std::string id = target->landmark_id;
  const map::Landmark* lm = g.map.findById(id);
  ASSERT_NE(lm, nullptr);

  // A red van between the camera and the number.
  const geometry::Rigid3 map_from_camera = pose.toRigid3() * rig.cameras[right].vehicle_from_camera;
  const Eigen::Vector3d mid = 0.3 * map_from_camera.translation() + 0.7 * lm->position;
  Box van;
  van.lo = Eigen::Vector3f(float(mid.x() - 0.7), float(mid.y() - 0.3), 0.0f);
  van.hi = Eigen::Vector3f(float(mid.x() + 0.7), float(mid.y() + 0.3), 2.0f);
  van.albedo = Eigen::Vector3f(0.9f, 0.02f, 0.02f);
  van.material = Material::kPillar;
  L.boxes.push_back(van);

  const auto after = annotateImage(g, 0, rig.cameras[right], pose);
  const io::LabelInstance* hidden = findLabel(after, id);
  ASSERT_NE(hidden, nullptr);
  EXPECT_GE(hidden->occluded_fraction, 0.9);
  // Numbers elsewhere stay visible.
  int visible = 0;
  for (const auto& l : after) visible += l.landmark_id != id && l.occluded_fraction < 0.5;
  EXPECT_GT(visible, 0) << after.size() << " labels";

  // The image shows the van at the projected centre of the number.
  LightingOptions light = testing::flatLight();
  const Renderer renderer(g, 0, rig, testing::raysOf(rig), light);
  const cv::Mat img = renderer.renderCamera(right, pose, 1);
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (const auto& p : hidden->polygon) c += 0.25 * p;
  const cv::Vec3b bgr = img.at<cv::Vec3b>(cvRound(c.y()), cvRound(c.x()));
  EXPECT_GT(bgr[2], 2 * bgr[1] + 20) << "expected red at " << c.transpose();
}

TEST(Occlusion, SegmentBlockedByBoxOnly) {
  GarageLevel L;
  Box b;
  b.lo = Eigen::Vector3f(1, -1, 0);
  b.hi = Eigen::Vector3f(2, 1, 1);
  L.boxes.push_back(b);
  EXPECT_TRUE(segmentBlocked(L, {0, 0, 0.5}, {3, 0, 0.5}));
  EXPECT_FALSE(segmentBlocked(L, {0, 0, 1.5}, {3, 0, 1.5}));
  EXPECT_FALSE(segmentBlocked(L, {0, 0, 0.5}, {0.9, 0, 0.5}));
  // A point on the box's own face is not hidden by that box.
  EXPECT_FALSE(segmentBlocked(L, {0, 0, 0.5}, {1.0, 0, 0.5}));
}

}  // namespace
}  // namespace parkloc::sim
