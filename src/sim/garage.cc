#include "sim/garage.h"

#include <algorithm>
#include <cmath>

#include "sim/garage_builder.h"

namespace parkloc::sim {

using detail::Builder;
using detail::buildLevel;
using detail::makeConcrete;
using detail::pick;
using detail::Rng;
using detail::uniform;

int Garage::levelIndex(const std::string& name) const {
  for (size_t i = 0; i < levels.size(); ++i)
    if (levels[i].name == name) return static_cast<int>(i);
  return -1;
}

Garage generateGarage(const GarageSpec& spec, uint64_t seed) {
  Garage g;
  g.spec = spec;
  g.seed = seed;
  Rng rng(seed);
  for (const auto& f : spec.fonts) g.fonts.push_back(resolveFontPath(f));
  g.ceiling_height = spec.ceiling_height + uniform(rng, -0.15, 0.15);
  const double cross_w = spec.aisle_width + 0.5;
  const int groups = (spec.slots_per_row + spec.slots_per_pillar - 1) / spec.slots_per_pillar;
  const double row_len =
      spec.slots_per_row * spec.slot_width + (groups - 1) * (spec.pillar_size + 0.1);
  g.aisle_x0 = cross_w;
  g.aisle_x1 = cross_w + row_len;
  g.cross_x0 = cross_w / 2;
  g.cross_x1 = g.aisle_x1 + cross_w / 2;
  for (int a = 0; a < spec.aisles; ++a)
    g.aisle_y.push_back(spec.slot_depth + spec.aisle_width / 2 +
                        a * (spec.aisle_width + 2 * spec.slot_depth));
  g.size = Eigen::Vector2d(g.aisle_x1 + cross_w,
                           g.aisle_y.back() + spec.aisle_width / 2 + spec.slot_depth);
  const float grey = static_cast<float>(uniform(rng, 0.38, 0.5));
  g.floor_albedo = Eigen::Vector3f(grey, grey * 0.98f, grey * 0.95f);
  g.wall_band = pick(
      rng, std::vector<Eigen::Vector3f>{
               {0.85f, 0.7f, 0.1f}, {0.2f, 0.4f, 0.7f}, {0.3f, 0.6f, 0.35f}, {0.6f, 0.6f, 0.6f}});
  g.wall_band_height = uniform(rng, 0.8, 1.3);
  g.concrete = MipTexture(makeConcrete(rng, 512), true);

  Builder b{spec, g, rng, TextRasterizer{}, {}};
  for (const auto& name : spec.levels) {
    g.levels.emplace_back();
    g.levels.back().name = name;
  }
  for (size_t i = 0; i < g.levels.size(); ++i) buildLevel(b, static_cast<int>(i));
  g.map = map::HdMap(b.map_landmarks, spec.name);
  return g;
}

}  // namespace parkloc::sim
