#pragma once
// What generateGarage (sim/garage.h) builds a garage with: one random stream drawn in a fixed
// order (the same spec and seed give the same garage), the text decals, and the state of one
// level while its rows, pillars, numbers, cars, floor words and lamps are placed. Internal to
// the sim module.
//
//   garage.cc            the garage's layout: size, aisles, cross aisles, colours, levels
//   garage_level.cc      one level: its style, the slot rows, then floor words, lamps, shade
//   garage_placement.cc  what stands or is painted in a row: pillars, numbers, parked cars
//   garage_numbering.cc  the texts: parking numbers, pillar labels, licence plates
//   garage_signs.cc      signs naming the level, where the spec asks for them
//   garage_surfaces.cc   decals, paint canvases, the concrete texture and the floor shade
#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "map/landmark.h"
#include "sim/garage.h"
#include "sim/text_raster.h"

namespace parkloc::sim::detail {

using Rng = std::mt19937_64;

inline double uniform(Rng& rng, double a, double b) {
  return std::uniform_real_distribution<double>(a, b)(rng);
}
inline bool chance(Rng& rng, double p) { return uniform(rng, 0.0, 1.0) < p; }
template <typename T>
const T& pick(Rng& rng, const std::vector<T>& v) {
  return v[std::uniform_int_distribution<size_t>(0, v.size() - 1)(rng)];
}

inline const Eigen::Vector3f kWhitePaint(0.88f, 0.88f, 0.85f);
inline const Eigen::Vector3f kYellowPaint(0.90f, 0.72f, 0.12f);

struct Builder {
  const GarageSpec& spec;
  Garage& g;
  Rng& rng;
  TextRasterizer raster;
  std::vector<map::Landmark> map_landmarks;

  // Adds a text decal whose ink box is the landmark's corners; fills width/height.
  Decal textDecal(map::Landmark& lm, const std::string& font, double texels_per_metre,
                  const Eigen::Vector3f& color, float opacity, double wear);
  // A solid rectangle centred on `center` with the given axes (plate backgrounds, pillar bands).
  static Decal solidDecal(const Eigen::Vector3d& center, const Eigen::Vector3d& axis_u,
                          const Eigen::Vector3d& axis_v, double w, double h,
                          const Eigen::Vector3f& color);
};

// One level under construction: its style, drawn once, its paint canvases and what has been
// placed on it so far.
struct LevelBuild {
  LevelBuild(Builder& builder, GarageLevel& level)
      : b(builder), spec(builder.spec), g(builder.g), rng(builder.rng), L(level), lv(level.name) {}
  Builder& b;
  const GarageSpec& spec;
  Garage& g;
  Rng& rng;
  GarageLevel& L;
  const std::string& lv;  // the level's name
  bool yellow_numbers = false;
  Eigen::Vector3f number_color;
  bool yellow_lines = false;
  int pillar_style = 0;  // which label a pillar carries (pillarLabel)
  Eigen::Vector3f pillar_band, pillar_ink;
  cv::Mat white, yellow;  // paint coverage at Garage::paint_texels_per_metre
  // Boxes standing on the floor, 10 cells per metre: the floor shade darkens around them.
  cv::Mat occupancy_mask;
  // Arrows and floor words placed so far (centre, radius): new ones keep clear of them.
  std::vector<std::pair<Eigen::Vector2d, double>> floor_marks;
  int number_index = 0, pillar_count = 0, plate_count = 0;

  cv::Mat& lines() { return yellow_lines ? yellow : white; }
  void markOccupancy(const Box& box, float strength);

  // garage_placement.cc: a pillar in the gap after slot column `column` (incremented), a
  // slot's painted number, a parked car in a slot, the other floor words of the level; each
  // draws from the random stream in a fixed order.
  void placePillar(double x, double y_edge, int side, char zone, int& column);
  void placeParkingNumber(const Slot& slot, double x, double y_edge, int side);
  void placeParkedCar(double x, double y_edge, int side);
  void placeFloorWords();
  // garage_signs.cc: signs naming the level on the walls and over the aisles (no random draw).
  void placeLevelSigns();
  // garage_surfaces.cc: mottling, stains, tyre marks and occlusion around the boxes placed.
  cv::Mat floorShade();
};

constexpr double kLineWidth = 0.12;  // painted slot lines, metres

// A text on a vertical face whose outward normal is `n` (horizontal): centred on `centre`,
// `height` tall, reading left to right for someone facing the face. Its width comes from
// Builder::textDecal.
map::Landmark verticalText(const std::string& id, const std::string& text, map::TextClass cls,
                           const std::string& level, const Eigen::Vector3d& n,
                           const Eigen::Vector3d& centre, double height);

// garage_level.cc
void buildLevel(Builder& b, int level_index);

// garage_numbering.cc
std::string pillarLabel(int style, const std::string& level, char zone, int column);
std::string randomPlate(Rng& rng);

// garage_surfaces.cc
cv::Mat makeConcrete(Rng& rng, int size);
// Mottling, oil stains in `slots`, tyre marks along the aisles' lanes and occlusion around what
// stands on the floor (`occupancy_mask`, 10 cells per metre): a multiplier on the floor albedo
// at Garage::shade_texels_per_metre.
cv::Mat floorShade(const Garage& g, Rng& rng, const std::vector<Slot>& slots,
                   const cv::Mat& occupancy_mask);
void paintRect(const Garage& g, cv::Mat& canvas, double x0, double y0, double x1, double y1);
void paintArrow(const Garage& g, cv::Mat& canvas, const Eigen::Vector2d& c,
                const Eigen::Vector2d& dir);

}  // namespace parkloc::sim::detail
