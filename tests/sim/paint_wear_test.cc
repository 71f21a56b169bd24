// The labels say how worn a painted number is: the wear the garage drew its ink with, for
// numbers painted worn, and none for intact numbers and for pillar text.
#include <gtest/gtest.h>

#include "sim/annotate.h"
#include "sim_test_util.h"

namespace parkloc::sim {
namespace {

// The labels of the right camera of a car driving east along the small garage's aisle.
std::vector<io::LabelInstance> labelsOfTheSouthRow(const GarageSpec& spec) {
  const geometry::Rig rig = testing::scaledRig(0.5);
  const Garage g = generateGarage(spec, 5);
  const geometry::Pose2 pose(14.0, g.aisle_y[0] + 0.5, 0.0);
  return annotateImage(g, 0, rig.cameras[3], pose);
}

TEST(PaintWear, WornNumbersAreLabelledWithTheirWearAndIntactOnesWithNone) {
  GarageSpec worn = testing::smallSpec();
  worn.worn_share = 1.0;
  int numbers = 0;
  for (const io::LabelInstance& l : labelsOfTheSouthRow(worn)) {
    if (l.cls != map::TextClass::kParkingNumber) continue;
    ++numbers;
    EXPECT_GE(l.paint_wear, 0.3) << l.text;  // the garage's range for worn numbers
    EXPECT_LE(l.paint_wear, 0.9) << l.text;
  }
  EXPECT_GT(numbers, 0);

  numbers = 0;
  for (const io::LabelInstance& l : labelsOfTheSouthRow(testing::smallSpec())) {  // none worn
    numbers += l.cls == map::TextClass::kParkingNumber;
    EXPECT_EQ(l.paint_wear, 0.0) << l.text;
  }
  EXPECT_GT(numbers, 0);
}

}  // namespace
}  // namespace parkloc::sim
