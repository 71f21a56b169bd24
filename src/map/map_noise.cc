#include "map/map_noise.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>

namespace parkloc::map {

double mapNoiseHeadingSigma(double position_sigma_m) {
  return (M_PI / 180.0) * position_sigma_m / 0.10;
}

HdMap perturbedMap(const HdMap& map, const MapNoise& noise) {
  const double heading_sigma = mapNoiseHeadingSigma(noise.position_sigma_m);
  const MapAccuracy accuracy{noise.position_sigma_m, heading_sigma};
  std::mt19937_64 rng(noise.seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  std::vector<Landmark> landmarks = map.landmarks();
  for (Landmark& l : landmarks) {
    const double dx = noise.position_sigma_m * unit(rng);
    const double dy = noise.position_sigma_m * unit(rng);
    const double turn = heading_sigma * unit(rng);
    const double width_scale = 1.0 + kMapNoiseRelativeSizeSigma * unit(rng);
    const double height_scale = 1.0 + kMapNoiseRelativeSizeSigma * unit(rng);
    l.position += Eigen::Vector3d(dx, dy, 0.0);
    l.heading += turn;
    if (l.surface == Surface::kVertical)
      l.normal = Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()) * l.normal;
    // A scale below a tenth would take 18 sigmas: kept positive for any seed all the same.
    l.width *= std::max(0.1, width_scale);
    l.height *= std::max(0.1, height_scale);
    l.accuracy = accuracy;
  }
  return HdMap(std::move(landmarks), map.name(), accuracy);
}

}  // namespace parkloc::map
