#pragma once
// A map with survey error, to measure how the localizer copes with one (`--map-noise`): a real
// map comes from a survey, a CAD drawing or a mapping drive, with centimetres of error and the
// nominal stencil sizes rather than the painted ink's.
#include <cstdint>

#include "map/hd_map.h"

namespace parkloc::map {

struct MapNoise {
  double position_sigma_m = 0.0;  // per horizontal axis, 1 sigma
  uint64_t seed = 0;
};

// The heading sigma that goes with a position sigma: 1 degree at 10 cm, in proportion
// otherwise (a survey that places a text to 10 cm turns it by about a degree).
double mapNoiseHeadingSigma(double position_sigma_m);
// Width and height are each scaled by 1 + N(0, this): the nominal size of a stencil.
inline constexpr double kMapNoiseRelativeSizeSigma = 0.05;

// A copy of `map` with every landmark moved by N(0, position_sigma_m) per horizontal axis,
// turned by N(0, mapNoiseHeadingSigma) about its centre (a vertical text's face normal turns
// with it), and its width and height scaled as above; heights (z) stay. The copy states its
// accuracy as the map-wide default and on every landmark (position_sigma_m and the heading
// sigma). Drawn from std::mt19937_64 seeded with `noise.seed`, landmark by landmark in map
// order: the same map and seed give the same copy.
HdMap perturbedMap(const HdMap& map, const MapNoise& noise);

}  // namespace parkloc::map
