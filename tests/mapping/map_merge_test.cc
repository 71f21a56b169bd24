#include "mapping/map_merge.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "common/error.h"

namespace parkloc::mapping {
namespace {

map::HdMap existingMap() {
  std::vector<map::Landmark> landmarks;
  for (int i = 0; i < 5; ++i) {
    map::Landmark l;
    l.text = "10" + std::to_string(i);
    l.level = "B1";
    l.id = "B1:" + l.text;
    l.position = {2.5 * i, 3.0, 0.0};
    l.width = 1.0;
    l.height = 0.45;
    l.accuracy.position_sigma = 0.02;
    landmarks.push_back(l);
  }
  return map::HdMap(landmarks);
}

TEST(MapMerge, ConfirmsMovesAndAddsInTheExistingFrame) {
  const map::HdMap existing = existingMap();
  // The built map in its own frame (turned and moved); 103 repainted 0.6 m further, one
  // number the existing map lacks, and 100 not seen.
  const geometry::Pose2 built_from_existing(4.0, -1.0, 0.8);
  std::vector<LandmarkEstimate> built;
  for (int i = 1; i < 5; ++i) {
    LandmarkEstimate l;
    l.text = "10" + std::to_string(i);
    Eigen::Vector2d p(2.5 * i + (i == 3 ? 0.6 : 0.0), 3.0);
    p = built_from_existing * p;
    l.parameters = {p.x(), p.y(), 0.8, 1.0, 0.45};
    l.position_sigma = 0.02;
    built.push_back(l);
  }
  LandmarkEstimate fresh;
  fresh.text = "105";
  const Eigen::Vector2d p = built_from_existing * Eigen::Vector2d(12.5, 3.0);
  fresh.parameters = {p.x(), p.y(), 0.8, 1.0, 0.45};
  built.push_back(fresh);

  const MapMerge merge = mergeMaps(existing, built, "B1", {});
  EXPECT_EQ(merge.confirmed, 3);
  ASSERT_EQ(merge.moved.size(), 1u);
  EXPECT_EQ(merge.moved[0], "103");
  ASSERT_EQ(merge.added.size(), 1u);
  EXPECT_EQ(merge.added[0], "105");
  EXPECT_EQ(merge.kept_unseen, 1);
  ASSERT_EQ(merge.landmarks.size(), 6u);
  std::map<std::string, double> x;
  for (const map::Landmark& l : merge.landmarks) x[l.text] = l.position.x();
  EXPECT_NEAR(x["103"], 7.5 + 0.6, 1e-6);
  EXPECT_NEAR(x["105"], 12.5, 1e-6);
  EXPECT_NEAR(x["102"], 5.0, 1e-6);
  EXPECT_NO_THROW(map::HdMap(merge.landmarks));
}

TEST(MapMerge, NoSharedTextIsAnError) {
  std::vector<LandmarkEstimate> built(2);
  built[0].text = "X1";
  built[1].text = "X2";
  built[1].parameters[kX] = 3.0;
  EXPECT_THROW(mergeMaps(existingMap(), built, "B1", {}), InputError);
}

}  // namespace
}  // namespace parkloc::mapping
