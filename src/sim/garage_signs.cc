#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "sim/garage_builder.h"

namespace parkloc::sim::detail {
namespace {

constexpr double kWallSignTextHeight = 0.40;     // ink height, metres
constexpr double kWallSignCentreHeight = 1.8;    // above the wall's coloured band
constexpr double kHangingSignTextHeight = 0.32;  // boards hung from the ceiling are smaller
constexpr double kBoardMargin = 0.14;            // board beyond the ink on every side
constexpr double kBoardThickness = 0.04;

}  // namespace

// Level signs: a garage with several floors that share one layout tells the driver which floor
// this is, on the end walls that a car faces before it turns and on boards hung over the
// aisles ("B2", "P3"). They are the text a localizer can tell the levels apart by when the
// parking numbers repeat on every level. Placed after everything else of the level and without
// a random draw, so a garage that asks for them has the same numbers, cars and words as one
// that does not; the boards take the level's pillar band and ink colours and the garage's
// first font.
void LevelBuild::placeLevelSigns() {
  const std::string& font = g.fonts.front();
  int count = 0;
  // A text `text_h` tall centred on `face_centre`, on the face of a board whose outward normal
  // is `n` (horizontal, along x or y); returns the ink's landmark.
  auto signText = [&](const Eigen::Vector3d& face_centre, const Eigen::Vector3d& n, double text_h) {
    map::Landmark lm = verticalText(fmt::format("{}:sign:{}", lv, ++count), lv,
                                    map::TextClass::kOther, lv, n, face_centre, text_h);
    L.box_decals.push_back(b.textDecal(lm, font, 600.0, pillar_ink, 1.0f, 0.0));
    L.texts.push_back({lm, true});
    b.map_landmarks.push_back(lm);
    return lm;
  };
  // The board spans `half_width` either side of `centre` across n, `half_height` up and down,
  // and from `back` to `front` along n.
  auto board = [&](const Eigen::Vector3d& centre, const Eigen::Vector3d& n, double half_width,
                   double half_height, double back, double front, int first_decal) {
    const Eigen::Vector3d across = n.cross(Eigen::Vector3d::UnitZ()).cwiseAbs();
    const Eigen::Vector3d a =
        centre + back * n - half_width * across - half_height * Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d c =
        centre + front * n + half_width * across + half_height * Eigen::Vector3d::UnitZ();
    Box box;
    box.lo = a.cwiseMin(c).cast<float>();
    box.hi = a.cwiseMax(c).cast<float>();
    box.albedo = pillar_band;
    box.material = Material::kWall;
    box.first_decal = first_decal;
    box.decal_count = static_cast<int>(L.box_decals.size()) - first_decal;
    L.boxes.push_back(box);
  };
  // On a wall at `wall_point` (on the floor, on the wall's surface), facing into the garage.
  auto wallSign = [&](const Eigen::Vector2d& wall_point, const Eigen::Vector3d& n) {
    const Eigen::Vector3d base(wall_point.x(), wall_point.y(), kWallSignCentreHeight);
    const int first = static_cast<int>(L.box_decals.size());
    const map::Landmark lm = signText(base + kBoardThickness * n, n, kWallSignTextHeight);
    board(base, n, 0.5 * lm.width + kBoardMargin, 0.5 * lm.height + kBoardMargin, 0.0,
          kBoardThickness, first);
  };
  // Over an aisle's centre line at x, read from both directions along the aisle.
  auto hangingSign = [&](double x, double y) {
    const double half_h = 0.5 * kHangingSignTextHeight + kBoardMargin;
    const Eigen::Vector3d centre(x, y, g.ceiling_height - 0.25 - half_h);
    const Eigen::Vector3d east = Eigen::Vector3d::UnitX();
    const int first = static_cast<int>(L.box_decals.size());
    const double t = 0.5 * kBoardThickness;
    const map::Landmark lm = signText(centre + t * east, east, kHangingSignTextHeight);
    signText(centre - t * east, -east, kHangingSignTextHeight);
    board(centre, east, 0.5 * lm.width + kBoardMargin, half_h, -t, t, first);
  };
  for (const double y : g.aisle_y) {
    wallSign({0.0, y}, Eigen::Vector3d::UnitX());
    wallSign({g.size.x(), y}, -Eigen::Vector3d::UnitX());
    hangingSign(0.5 * (g.aisle_x0 + g.aisle_x1), y);
  }
  for (const double x : {g.cross_x0, g.cross_x1}) {
    wallSign({x, 0.0}, Eigen::Vector3d::UnitY());
    wallSign({x, g.size.y()}, -Eigen::Vector3d::UnitY());
  }
}

}  // namespace parkloc::sim::detail
