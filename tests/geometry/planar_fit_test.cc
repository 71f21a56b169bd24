#include "geometry/planar_fit.h"

#include <gtest/gtest.h>

#include <random>

namespace parkloc::geometry {
namespace {

std::vector<Eigen::Vector2d> somePoints() {
  return {{0.0, 0.0}, {5.0, 1.0}, {2.0, 7.0}, {-3.0, 4.0}, {8.0, -2.0}};
}

TEST(PlanarFit, RecoversARigidTransformExactly) {
  const Pose2 truth(3.0, -2.0, 0.7);
  std::vector<Eigen::Vector2d> to;
  for (const auto& p : somePoints()) to.push_back(truth * p);
  const auto fit = fitPlanar(somePoints(), to, /*with_scale=*/false);
  ASSERT_TRUE(fit);
  EXPECT_NEAR(fit->to_from_from.x, 3.0, 1e-9);
  EXPECT_NEAR(fit->to_from_from.y, -2.0, 1e-9);
  EXPECT_NEAR(fit->to_from_from.yaw, 0.7, 1e-9);
  EXPECT_DOUBLE_EQ(fit->scale, 1.0);
  EXPECT_LT(fit->rms, 1e-9);
}

TEST(PlanarFit, RecoversASimilarityAndReportsResiduals) {
  const Pose2 truth(-1.0, 4.0, -2.0);
  std::vector<Eigen::Vector2d> to;
  for (const auto& p : somePoints()) to.push_back(truth * Eigen::Vector2d(1.2 * p));
  const auto fit = fitPlanar(somePoints(), to, /*with_scale=*/true);
  ASSERT_TRUE(fit);
  EXPECT_NEAR(fit->scale, 1.2, 1e-9);
  EXPECT_NEAR(fit->to_from_from.yaw, -2.0, 1e-9);
  // A rigid fit of the same points cannot absorb the scale: it leaves residuals.
  const auto rigid = fitPlanar(somePoints(), to, /*with_scale=*/false);
  ASSERT_TRUE(rigid);
  EXPECT_GT(rigid->rms, 0.1);
  ASSERT_EQ(rigid->residuals.size(), somePoints().size());
}

TEST(PlanarFit, LeastSquaresUnderNoiseAndDegenerateInput) {
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.01);
  const Pose2 truth(1.0, 1.0, 0.3);
  std::vector<Eigen::Vector2d> from, to;
  for (int i = 0; i < 200; ++i) {
    from.emplace_back(i % 20, i / 20);
    to.push_back(truth * from.back() + Eigen::Vector2d(noise(rng), noise(rng)));
  }
  const auto fit = fitPlanar(from, to, false);
  ASSERT_TRUE(fit);
  EXPECT_NEAR(fit->to_from_from.yaw, 0.3, 1e-3);
  EXPECT_NEAR(fit->rms, 0.01 * std::sqrt(2.0), 0.003);
  EXPECT_FALSE(fitPlanar({{1.0, 1.0}}, {{2.0, 2.0}}, false));
  EXPECT_FALSE(fitPlanar({{1.0, 1.0}, {1.0, 1.0}}, {{2.0, 2.0}, {3.0, 3.0}}, false));
}

}  // namespace
}  // namespace parkloc::geometry
