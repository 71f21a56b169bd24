#pragma once
// The finish of the floor: a coloured epoxy coating (green, grey or blue, smooth, with little
// of the concrete's grain showing) and a glossy surface, sealed or wet, that mirrors the
// ceiling lamps as soft highlights. Both are common in real garages and both change what the
// camera sees around painted numbers: a coloured ground under the paint, bright streaks of
// mirrored lamps across it.
#include <random>

#include "sim/garage.h"

namespace parkloc::sim {

// Coats the garage's floor: its albedo becomes one of the usual epoxy colours and the concrete
// grain fades by `strength` (in (0, 1]); the coat is mildly glossy (Garage::gloss).
void coatWithEpoxy(Garage& garage, float strength, std::mt19937_64& rng);

// Makes the floor glossy with sheen `strength` (in (0, 1]) and lays puddles over each level
// (GarageLevel::floor_wetness), where the mirror is sharper and the concrete darker.
void makeFloorGlossy(Garage& garage, float strength, std::mt19937_64& rng);

// The Schlick approximation of the Fresnel reflectance of a dielectric with normal-incidence
// reflectance `f0` at cosine `cos_incidence` (Schlick, "An inexpensive BRDF model for
// physically-based rendering", 1994); water and epoxy have f0 of about 0.02-0.05.
float fresnelSchlick(float cos_incidence, float f0 = 0.04f);

}  // namespace parkloc::sim
