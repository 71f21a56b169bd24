#include "localize/paper_modules.h"

#include <gtest/gtest.h>

namespace parkloc::localize {
namespace {

// A square observation of side `side` pixels.
LandmarkObservation observed(int camera, const std::string& id, double side) {
  LandmarkObservation o;
  o.camera = camera;
  o.landmark_id = id;
  o.pixels = {Eigen::Vector2d(0, 0), Eigen::Vector2d(side, 0), Eigen::Vector2d(side, side),
              Eigen::Vector2d(0, side)};
  return o;
}

std::vector<std::pair<int, std::string>> cameraAndId(const std::vector<LandmarkObservation>& obs) {
  std::vector<std::pair<int, std::string>> out;
  for (const auto& o : obs) out.emplace_back(o.camera, o.landmark_id);
  return out;
}

const std::vector<LandmarkObservation> kSeen = {observed(0, "a", 10), observed(0, "b", 30),
                                                observed(1, "a", 40), observed(1, "b", 20)};

TEST(PaperModulesTest, WithBothModulesEveryObservationIsUsed) {
  EXPECT_EQ(selectForModules(kSeen, {}).size(), 4u);
}

TEST(PaperModulesTest, WithoutMcrpEachLandmarkKeepsItsFirstCamera) {
  PaperModuleOptions options;
  options.mcrp = false;
  EXPECT_EQ(cameraAndId(selectForModules(kSeen, options)),
            (std::vector<std::pair<int, std::string>>{{0, "a"}, {0, "b"}}));
}

TEST(PaperModulesTest, WithoutMcapOnlyTheLandmarkThatLooksLargestIsUsed) {
  PaperModuleOptions options;
  options.mcap = false;
  // "a" looks largest (40 px in camera 1): both its observations stay.
  EXPECT_EQ(cameraAndId(selectForModules(kSeen, options)),
            (std::vector<std::pair<int, std::string>>{{0, "a"}, {1, "a"}}));
  options.mcrp = false;
  // MCRP first: camera 0's "a" (10 px) and "b" (30 px) remain, and "b" is larger.
  EXPECT_EQ(cameraAndId(selectForModules(kSeen, options)),
            (std::vector<std::pair<int, std::string>>{{0, "b"}}));
}

TEST(PaperModulesTest, TheAfmOptionsAreClampedToAUsableQueue) {
  PaperModuleOptions options;
  options.afm_queue_length = 0;
  options.afm_reset_after_rejections = -5;
  const BoxPlotFilterOptions afm = afmOptions(options);
  EXPECT_EQ(afm.queue_length, 1u);
  EXPECT_EQ(afm.reset_after_rejections, 0u);
  EXPECT_EQ(afm.iqr_factor, options.afm_iqr_factor);
}

}  // namespace
}  // namespace parkloc::localize
