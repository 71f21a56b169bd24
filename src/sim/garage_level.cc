#include <algorithm>
#include <cmath>

#include "sim/garage_builder.h"

namespace parkloc::sim::detail {

// One level: its style (number and line colours, pillar labels and bands), then row by row
// the slots with their lines, pillars, numbers and cars, the aisle arrows, the other floor
// words, the lamps and the floor shade, then the level signs where the spec asks for them. Every
// draw from the random stream happens in this order, so a level is the same for the same seed.
void buildLevel(Builder& b, int level_index) {
  const GarageSpec& spec = b.spec;
  Garage& g = b.g;
  Rng& rng = b.rng;
  GarageLevel& L = g.levels[level_index];
  const std::string& lv = L.name;
  const double aw = spec.aisle_width, depth = spec.slot_depth, sw = spec.slot_width;
  const double pillar_gap = spec.pillar_size + 0.1;
  LevelBuild lb{b, L};

  lb.yellow_numbers = chance(rng, spec.yellow_share);
  lb.number_color = lb.yellow_numbers ? kYellowPaint : kWhitePaint;
  lb.yellow_lines = chance(rng, 0.35);
  lb.pillar_style = std::uniform_int_distribution<int>(0, 3)(rng);
  lb.pillar_band = pick(rng, std::vector<Eigen::Vector3f>{{0.9f, 0.75f, 0.1f},
                                                          {0.85f, 0.85f, 0.82f},
                                                          {0.2f, 0.45f, 0.8f},
                                                          {0.85f, 0.3f, 0.2f},
                                                          {0.3f, 0.65f, 0.35f}});
  lb.pillar_ink = lb.pillar_band.sum() > 1.6f ? Eigen::Vector3f(0.05f, 0.05f, 0.06f)
                                              : Eigen::Vector3f(0.95f, 0.95f, 0.95f);

  const int paint_w = static_cast<int>(std::ceil(g.size.x() * g.paint_texels_per_metre));
  const int paint_h = static_cast<int>(std::ceil(g.size.y() * g.paint_texels_per_metre));
  lb.white = cv::Mat(paint_h, paint_w, CV_8UC1, cv::Scalar(0));
  lb.yellow = cv::Mat(paint_h, paint_w, CV_8UC1, cv::Scalar(0));
  cv::Mat& lines = lb.lines();
  const double lw = kLineWidth;
  lb.occupancy_mask = cv::Mat(static_cast<int>(g.size.y() * 10), static_cast<int>(g.size.x() * 10),
                              CV_32F, cv::Scalar(0));

  for (int aisle = 0; aisle < spec.aisles; ++aisle) {
    const double yc = g.aisle_y[aisle];
    for (int side : {+1, -1}) {
      const double y_edge = yc + side * aw / 2;
      const int row = aisle * 2 + (side > 0 ? 1 : 0);
      const char zone = static_cast<char>('A' + row);
      // Row geometry along x: groups of slots separated by pillar gaps.
      double x = g.aisle_x0;
      int column = 0;
      paintRect(g, lines, g.aisle_x0 - lw / 2, std::min(y_edge, y_edge + side * depth),
                g.aisle_x0 + lw / 2, std::max(y_edge, y_edge + side * depth));
      for (int k = 0; k < spec.slots_per_row; ++k) {
        if (k > 0 && k % spec.slots_per_pillar == 0) {
          lb.placePillar(x, y_edge, side, zone, column);
          x += pillar_gap;
        }
        // Slot k spans [x, x + sw].
        Slot slot;
        slot.center = Eigen::Vector2d(x + sw / 2, y_edge + side * depth / 2);
        slot.aisle = aisle;
        slot.side = side;
        slot.number =
            formatParkingNumber(spec.numbering, lv, spec.first_number + lb.number_index, zone);
        if (spec.numbering == NumberingScheme::kZoneLetter)
          slot.number = formatParkingNumber(spec.numbering, lv, spec.first_number + k, zone);
        ++lb.number_index;
        paintRect(g, lines, x + sw - lw / 2, std::min(y_edge, y_edge + side * depth),
                  x + sw + lw / 2, std::max(y_edge, y_edge + side * depth));
        lb.placeParkingNumber(slot, x, y_edge, side);
        // A parked car in a share of the slots.
        slot.occupied = chance(rng, spec.occupancy);
        if (slot.occupied) lb.placeParkedCar(x, y_edge, side);
        L.slots.push_back(slot);
        x += sw;
      }
      paintRect(g, lines, x - lw / 2, std::min(y_edge, y_edge + side * depth), x + lw / 2,
                std::max(y_edge, y_edge + side * depth));
      // Edge line between row and aisle on some garages.
      if (lb.yellow_lines) paintRect(g, lines, g.aisle_x0, y_edge - lw / 2, x, y_edge + lw / 2);
    }
    // Direction arrows in the aisle.
    for (double ax = g.aisle_x0 + uniform(rng, 3.0, 8.0); ax < g.aisle_x1 - 3.0;
         ax += uniform(rng, 12.0, 20.0)) {
      const Eigen::Vector2d c(ax, yc + (chance(rng, 0.5) ? 1.4 : -1.4));
      paintArrow(g, lb.white, c, chance(rng, 0.5) ? Eigen::Vector2d(1, 0) : Eigen::Vector2d(-1, 0));
      lb.floor_marks.push_back({c, 1.3});
    }
  }

  lb.placeFloorWords();

  L.paint_white = MipTexture(lb.white);
  L.paint_yellow = MipTexture(lb.yellow);

  // Lamps: tubes along the aisles and cross aisles every ~5 m, sparser over the slot rows.
  for (int aisle = 0; aisle < spec.aisles; ++aisle)
    for (double x = g.aisle_x0 + 1.5; x < g.aisle_x1; x += 5.0)
      L.lamps.push_back(
          {Eigen::Vector2f(float(x), float(g.aisle_y[aisle])), Eigen::Vector2f(0.6f, 0.07f)});
  for (double cx : {g.cross_x0, g.cross_x1})
    for (double y = 3.0; y < g.size.y() - 1.0; y += 5.5)
      L.lamps.push_back({Eigen::Vector2f(float(cx), float(y)), Eigen::Vector2f(0.07f, 0.6f)});

  L.floor_shade = lb.floorShade();
  if (spec.level_signs) lb.placeLevelSigns();
}

}  // namespace parkloc::sim::detail
