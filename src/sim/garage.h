#pragma once
// The procedural garage: per level, the boxes (pillars, parked cars), painted floor
// markings, text decals, ceiling lamps; the HD map with every fixed text landmark. All
// geometry is axis-aligned in the map frame (aisles run along x).
#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "map/hd_map.h"
#include "sim/mip_texture.h"
#include "sim/scenario.h"

namespace parkloc::sim {

// kCarBody boxes reach the floor: the renderer draws wheels, sills and lights on them.
enum class Material : uint8_t { kPillar, kCarBody, kCarGlass, kWall };

// An axis-aligned box; its decals (pillar text, plates) are box_decals[first_decal, +count).
struct Box {
  Eigen::Vector3f lo, hi;
  Eigen::Vector3f albedo{0.5f, 0.5f, 0.5f};
  Material material = Material::kPillar;
  int first_decal = 0;
  int decal_count = 0;
};

// A textured rectangle on a surface: point = origin + u * axis_u + v * axis_v, u in
// [0, size_u], v in [0, size_v] (origin = top-left of the text, axis_u = reading direction,
// axis_v = down the glyphs). texture < 0: a solid rectangle (a licence plate's background).
struct Decal {
  Eigen::Vector3f origin, axis_u, axis_v;
  float size_u = 0.0f, size_v = 0.0f;
  float texels_per_metre = 250.0f;
  int pad = 0;  // background texels around the ink in the texture
  int texture = -1;
  Eigen::Vector3f color{1.0f, 1.0f, 1.0f};
  float opacity = 1.0f;
  // How worn the ink is (wearInk's severity: 0 intact, up to 1 mostly erased).
  float wear = 0.0f;
  // The share of the rasterized ink that the wear left (1: intact): the worn text's mean
  // ink, for its contrast against the floor (Renderer::floorInkContrast).
  float ink_kept = 1.0f;
  // A painted patch under the text (number_styles.h): its decal in the same list, -1: none.
  // The text's contrast is then taken against the patch, not the bare floor.
  int backing = -1;
};

// Ceiling lamp: an emissive rectangle on the ceiling, also the light source of the level.
struct Lamp {
  Eigen::Vector2f center;
  Eigen::Vector2f half_size;
};

struct Slot {
  Eigen::Vector2d center;
  int aisle = 0;
  int side = +1;  // +1 north of the aisle, -1 south
  bool occupied = false;
  std::string number;
};

// Text visible in the images: the map's landmarks plus licence plates of parked cars,
// which are not in the map (cars move).
struct TextItem {
  map::Landmark landmark;
  bool in_map = true;
  int floor_decal = -1;  // its decal in GarageLevel::floor_decals (painted floor text)
};

struct GarageLevel {
  std::string name;
  std::vector<Box> boxes;
  std::vector<Decal> box_decals;
  std::vector<Decal> floor_decals;
  std::vector<Lamp> lamps;
  std::vector<Slot> slots;
  std::vector<TextItem> texts;
  // Painted lines and arrows, coverage at paint_texels_per_metre, origin at (0, 0).
  MipTexture paint_white, paint_yellow;
  // Stains, tyre marks and ambient occlusion: multiplier on the floor albedo, 5 cm texels.
  cv::Mat floor_shade;  // CV_32F
  // The appearance's floor wear (sim/floor_wear.h): tyre streaks, oil, patches and cracks as a
  // multiplier over the floor and its paint, at Garage::grime_texels_per_metre; empty: none.
  cv::Mat floor_grime;  // CV_32F
  // Where a glossy floor is wet (1) or only sealed (0) (sim/floor_finish.h), at
  // Garage::wetness_texels_per_metre; empty with no gloss.
  cv::Mat floor_wetness;  // CV_32F
};

struct Garage {
  GarageSpec spec;
  uint64_t seed = 0;
  Eigen::Vector2d size{0.0, 0.0};  // interior floor [0, size.x] x [0, size.y]
  double ceiling_height = 2.8;
  std::vector<double> aisle_y;            // centre line of each aisle
  double aisle_x0 = 0.0, aisle_x1 = 0.0;  // where the slot rows begin and end
  double cross_x0 = 0.0, cross_x1 = 0.0;  // centre lines of the two cross aisles
  std::vector<GarageLevel> levels;
  std::vector<MipTexture> textures;  // text decal textures of every level
  MipTexture concrete;               // tiling floor texture, 1 cm texels
  double concrete_texels_per_metre = 100.0;
  double paint_texels_per_metre = 50.0;
  double shade_texels_per_metre = 20.0;
  double grime_texels_per_metre = 40.0;
  double wetness_texels_per_metre = 5.0;
  // The floor's mirror-like sheen (sim/floor_finish.h): 0 matte concrete.
  float gloss = 0.0f;
  Eigen::Vector3f floor_albedo{0.45f, 0.44f, 0.42f};
  Eigen::Vector3f wall_albedo{0.7f, 0.7f, 0.68f};
  Eigen::Vector3f wall_band{0.85f, 0.7f, 0.1f};
  double wall_band_height = 1.0;
  std::vector<std::string> fonts;  // resolved font paths used
  map::HdMap map;

  int levelIndex(const std::string& name) const;  // -1 when unknown
};

// Builds a garage from its spec; the same spec and seed give the same garage.
Garage generateGarage(const GarageSpec& spec, uint64_t seed);

// The parking-number text of slot `index` (0-based, along the level) per the scheme.
std::string formatParkingNumber(NumberingScheme scheme, const std::string& level, int number,
                                int zone);

}  // namespace parkloc::sim
