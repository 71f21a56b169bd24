#include "mapping/anchor_fit.h"

#include <gtest/gtest.h>

#include "common/error.h"

namespace parkloc::mapping {
namespace {

std::vector<LandmarkEstimate> builtLandmarks() {
  std::vector<LandmarkEstimate> out;
  const double xy[4][2] = {{0.0, 0.0}, {2.5, 0.0}, {5.0, 3.0}, {1.0, 6.0}};
  for (int i = 0; i < 4; ++i) {
    LandmarkEstimate l;
    l.text = "P" + std::to_string(i);
    l.parameters = {xy[i][0], xy[i][1], 0.2, 1.0, 0.5};
    l.position_sigma = 0.01;
    out.push_back(l);
  }
  return out;
}

TEST(AnchorFit, ASimilarityPutsTheMapIntoTheSurveyedFrame) {
  auto built = builtLandmarks();
  // The survey frame: the built map turned, moved and 3 % larger (the odometry ran short).
  const geometry::Pose2 frame(10.0, 20.0, 0.5);
  std::vector<io::Anchor> anchors;
  for (int i : {0, 2, 3})
    anchors.push_back(
        {built[i].text, frame * Eigen::Vector2d(1.03 * Eigen::Vector2d(built[i].parameters[kX],
                                                                       built[i].parameters[kY]))});
  anchors.push_back({"NOT-BUILT", {0.0, 0.0}});
  const AnchorFit fit = fitAnchors(built, anchors, /*with_scale=*/true);
  EXPECT_NEAR(fit.fit.scale, 1.03, 1e-9);
  EXPECT_LT(fit.fit.rms, 1e-9);
  ASSERT_EQ(fit.unmatched.size(), 1u);
  EXPECT_EQ(fit.unmatched[0], "NOT-BUILT");
  for (auto& l : built) applyFit(fit.fit, l);
  const Eigen::Vector2d expected = frame * Eigen::Vector2d(1.03 * Eigen::Vector2d(2.5, 0.0));
  EXPECT_NEAR(built[1].parameters[kX], expected.x(), 1e-9);
  EXPECT_NEAR(built[1].parameters[kY], expected.y(), 1e-9);
  EXPECT_NEAR(built[1].parameters[kHeading], 0.7, 1e-9);
  EXPECT_NEAR(built[1].parameters[kWidth], 1.03, 1e-9);
  EXPECT_NEAR(*built[1].position_sigma, 0.0103, 1e-9);
}

TEST(AnchorFit, ARigidFitReportsTheResidualOfAWrongAnchor) {
  const auto built = builtLandmarks();
  std::vector<io::Anchor> anchors;
  for (const auto& l : built) anchors.push_back({l.text, {l.parameters[kX], l.parameters[kY]}});
  anchors[2].position.x() += 0.4;  // a surveying error
  const AnchorFit fit = fitAnchors(built, anchors, /*with_scale=*/false);
  const auto worst = std::max_element(fit.fit.residuals.begin(), fit.fit.residuals.end());
  EXPECT_EQ(fit.used[static_cast<size_t>(worst - fit.fit.residuals.begin())], "P2");
  EXPECT_GT(*worst, 0.2);
}

TEST(AnchorFit, FewerThanTwoMatchingAnchorsIsAnError) {
  EXPECT_THROW(fitAnchors(builtLandmarks(), {{"P1", {0.0, 0.0}}, {"X", {1.0, 1.0}}}, false),
               InputError);
}

}  // namespace
}  // namespace parkloc::mapping
