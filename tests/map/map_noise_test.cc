#include "map/map_noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace parkloc::map {
namespace {

HdMap grid(int n) {
  std::vector<Landmark> landmarks;
  for (int i = 0; i < n; ++i) {
    Landmark l;
    l.id = l.text = "N" + std::to_string(i);
    l.level = "B1";
    l.position = {0.5 * i, 2.0, i % 3 == 0 ? 1.5 : 0.0};
    l.heading = 0.3;
    l.width = 1.0;
    l.height = 0.5;
    if (i % 3 == 0) {  // a pillar face, reading along the heading, facing 90 degrees to its right
      l.cls = TextClass::kPillar;
      l.surface = Surface::kVertical;
      l.normal = Eigen::Vector3d(std::sin(0.3), -std::cos(0.3), 0.0);
    }
    landmarks.push_back(l);
  }
  return HdMap(landmarks, "grid");
}

TEST(MapNoise, SameSeedSameMapOtherSeedOtherMap) {
  const HdMap exact = grid(30);
  const HdMap a = perturbedMap(exact, {0.1, 7});
  const HdMap b = perturbedMap(exact, {0.1, 7});
  const HdMap c = perturbedMap(exact, {0.1, 8});
  for (size_t i = 0; i < exact.size(); ++i) {
    EXPECT_EQ(a.landmarks()[i].position, b.landmarks()[i].position);
    EXPECT_EQ(a.landmarks()[i].width, b.landmarks()[i].width);
    EXPECT_NE(a.landmarks()[i].position, c.landmarks()[i].position);
  }
}

TEST(MapNoise, ErrorsHaveTheStatedSpread) {
  const HdMap exact = grid(3000);
  const double sigma = 0.03;
  const HdMap noisy = perturbedMap(exact, {sigma, 1});
  double sx = 0, sy = 0, sh = 0, sw = 0, sz = 0;
  for (size_t i = 0; i < exact.size(); ++i) {
    const Landmark& e = exact.landmarks()[i];
    const Landmark& n = noisy.landmarks()[i];
    sx += std::pow(n.position.x() - e.position.x(), 2);
    sy += std::pow(n.position.y() - e.position.y(), 2);
    sz += std::abs(n.position.z() - e.position.z());
    sh += std::pow(n.heading - e.heading, 2);
    sw += std::pow(n.width / e.width - 1.0, 2);
  }
  const double count = static_cast<double>(exact.size());
  EXPECT_NEAR(std::sqrt(sx / count), sigma, 0.1 * sigma);
  EXPECT_NEAR(std::sqrt(sy / count), sigma, 0.1 * sigma);
  EXPECT_EQ(sz, 0.0);
  // 1 degree at 10 cm: 0.3 degrees at 3 cm.
  EXPECT_NEAR(std::sqrt(sh / count), 0.3 * M_PI / 180.0, 0.03 * M_PI / 180.0);
  EXPECT_NEAR(std::sqrt(sw / count), kMapNoiseRelativeSizeSigma, 0.005);
}

TEST(MapNoise, PillarFaceNormalTurnsWithTheHeading) {
  const HdMap exact = grid(30);
  const HdMap noisy = perturbedMap(exact, {0.2, 3});
  for (size_t i = 0; i < exact.size(); i += 3) {
    const Landmark& e = exact.landmarks()[i];
    const Landmark& n = noisy.landmarks()[i];
    ASSERT_EQ(n.surface, Surface::kVertical);
    const double normal_turn = std::atan2(n.normal.y(), n.normal.x()) -
                               std::atan2(e.normal.y(), e.normal.x());
    EXPECT_NEAR(std::remainder(normal_turn - (n.heading - e.heading), 2 * M_PI), 0.0, 1e-12);
    EXPECT_NEAR(n.normal.norm(), 1.0, 1e-12);
    EXPECT_NEAR(n.normal.dot(n.readingDirection()), 0.0, 1e-12);  // still across the face
  }
}

TEST(MapNoise, StatesItsAccuracy) {
  const HdMap noisy = perturbedMap(grid(5), {0.1, 2});
  EXPECT_EQ(noisy.accuracy().position_sigma, 0.1);
  EXPECT_NEAR(*noisy.accuracy().heading_sigma, M_PI / 180.0, 1e-15);
  for (const Landmark& l : noisy.landmarks()) EXPECT_EQ(l.accuracy, noisy.accuracy());
  EXPECT_EQ(noisy.name(), "grid");
}

}  // namespace
}  // namespace parkloc::map
