#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "sim/garage_builder.h"

namespace parkloc::sim::detail {

void LevelBuild::placePillar(double x, double y_edge, int side, char zone, int& column) {
  const double pillar_gap = spec.pillar_size + 0.1;
  const double H = g.ceiling_height;
  // Pillar in the gap, its aisle face 0.3 m inside the row.
  const double px = x + pillar_gap / 2;
  const double ps = spec.pillar_size;
  const double py_near = y_edge + side * 0.3;
  Box p;
  p.lo = Eigen::Vector3f(float(px - ps / 2), float(std::min(py_near, py_near + side * ps)), 0.0f);
  p.hi =
      Eigen::Vector3f(float(px + ps / 2), float(std::max(py_near, py_near + side * ps)), float(H));
  p.albedo = Eigen::Vector3f(0.62f, 0.62f, 0.6f);
  p.material = Material::kPillar;
  p.first_decal = static_cast<int>(L.box_decals.size());
  ++column;
  ++pillar_count;
  const std::string text = pillarLabel(pillar_style, lv, zone, column);
  const double text_h = uniform(rng, 0.2, 0.3);
  const double text_z = uniform(rng, 1.3, 1.7);
  const std::string font = pick(rng, g.fonts);
  // Text on the aisle face and both faces along the aisle.
  const Eigen::Vector3d centre(px, py_near + side * ps / 2, 0.0);
  const std::pair<Eigen::Vector3d, const char*> faces[] = {{Eigen::Vector3d(0, -side, 0), "aisle"},
                                                           {Eigen::Vector3d(1, 0, 0), "east"},
                                                           {Eigen::Vector3d(-1, 0, 0), "west"}};
  for (const auto& [n, face_name] : faces) {
    map::Landmark lm = verticalText(fmt::format("{}:pillar:{}:{}", lv, pillar_count, face_name),
                                    text, map::TextClass::kPillar, lv, n,
                                    centre + n * (ps / 2) + Eigen::Vector3d(0, 0, text_z), text_h);
    const Eigen::Vector3d right = (-n).cross(Eigen::Vector3d::UnitZ());
    Decal ink = b.textDecal(lm, font, 600.0, pillar_ink, 1.0f, 0.0);
    if (lm.width > ps - 0.06) {  // too wide for the face: shrink
      lm.height *= (ps - 0.06) / lm.width;
      g.textures.pop_back();
      ink = b.textDecal(lm, font, 600.0, pillar_ink, 1.0f, 0.0);
    }
    const Eigen::Vector3d down(0, 0, -1);
    L.box_decals.push_back(
        Builder::solidDecal(lm.position, right, down, ps * 0.999, lm.height + 0.16, pillar_band));
    L.box_decals.push_back(ink);
    L.texts.push_back({lm, true});
    b.map_landmarks.push_back(lm);
  }
  p.decal_count = static_cast<int>(L.box_decals.size()) - p.first_decal;
  L.boxes.push_back(p);
  markOccupancy(p, 1.0f);
}

void LevelBuild::placeParkingNumber(const Slot& slot, double x, double y_edge, int side) {
  const double sw = spec.slot_width;
  // Painted parking number at the aisle end, read by a driver facing the slot.
  map::Landmark lm;
  lm.id = fmt::format("{}:{}", lv, slot.number);
  lm.text = slot.number;
  lm.cls = map::TextClass::kParkingNumber;
  lm.level = lv;
  lm.surface = map::Surface::kGround;
  lm.heading = side > 0 ? 0.0 : M_PI;
  lm.height = spec.number_height * uniform(rng, 0.97, 1.03);
  const bool worn = chance(rng, spec.worn_share);
  const double wear = worn ? uniform(rng, 0.3, 0.9) : 0.0;
  const float opacity =
      static_cast<float>(worn ? uniform(rng, 0.55, 0.9) : uniform(rng, 0.85, 1.0));
  const std::string font = pick(rng, g.fonts);
  const Eigen::Vector3f color =
      chance(rng, 0.1) ? (yellow_numbers ? kWhitePaint : kYellowPaint) : number_color;
  for (int attempt = 0; attempt < 3; ++attempt) {
    lm.position = Eigen::Vector3d(x + sw / 2, y_edge + side * (0.35 + lm.height / 2), 0.0);
    Decal d = b.textDecal(lm, font, 250.0, color, opacity, wear);
    if (lm.width <= sw - 0.4 || attempt == 2) {
      L.floor_decals.push_back(d);
      break;
    }
    g.textures.pop_back();
    lm.height *= (sw - 0.45) / lm.width;
  }
  L.texts.push_back({lm, true, static_cast<int>(L.floor_decals.size()) - 1});
  b.map_landmarks.push_back(lm);
}

// A parked car: a lower body box (the renderer draws wheels, sills and lamps on it), a glass
// cabin box, and a licence plate on the end facing the aisle.
void LevelBuild::placeParkedCar(double x, double y_edge, int side) {
  const double depth = spec.slot_depth, sw = spec.slot_width;
  const double len = uniform(rng, 4.1, 4.9), wid = uniform(rng, 1.7, 1.9);
  const double height = uniform(rng, 1.4, 1.65);
  const double back_gap = uniform(rng, 0.15, 0.9);
  const double cx = x + sw / 2 + uniform(rng, -0.15, 0.15);
  const double y_back = y_edge + side * depth;
  const double y_far = y_back - side * back_gap;  // end at the back of the slot
  const double y_near = y_far - side * len;       // end facing the aisle
  const double ylo = std::min(y_far, y_near), yhi = std::max(y_far, y_near);
  const Eigen::Vector3f paint = pick(rng, std::vector<Eigen::Vector3f>{{0.85f, 0.85f, 0.85f},
                                                                       {0.06f, 0.06f, 0.07f},
                                                                       {0.55f, 0.56f, 0.58f},
                                                                       {0.3f, 0.31f, 0.33f},
                                                                       {0.1f, 0.2f, 0.45f},
                                                                       {0.55f, 0.07f, 0.06f},
                                                                       {0.12f, 0.25f, 0.15f},
                                                                       {0.6f, 0.55f, 0.45f}});
  Box body;
  body.lo = Eigen::Vector3f(float(cx - wid / 2), float(ylo), 0.0f);
  body.hi = Eigen::Vector3f(float(cx + wid / 2), float(yhi), float(height * 0.6));
  body.albedo = paint;
  body.material = Material::kCarBody;
  // Licence plate on the end facing the aisle.
  body.first_decal = static_cast<int>(L.box_decals.size());
  map::Landmark plate;
  plate.id = fmt::format("{}:plate:{}", lv, ++plate_count);
  plate.text = randomPlate(rng);
  plate.cls = map::TextClass::kOther;
  plate.level = lv;
  plate.surface = map::Surface::kVertical;
  plate.normal = Eigen::Vector3d(0, -side, 0);
  const Eigen::Vector3d right = (-plate.normal).cross(Eigen::Vector3d::UnitZ());
  plate.heading = std::atan2(right.y(), right.x());
  plate.position = Eigen::Vector3d(cx, y_near, uniform(rng, 0.42, 0.52));
  plate.height = 0.075;
  const bool yellow_plate = chance(rng, 0.2);
  const Eigen::Vector3f plate_bg =
      yellow_plate ? Eigen::Vector3f(0.85f, 0.7f, 0.1f) : Eigen::Vector3f(0.88f, 0.88f, 0.88f);
  Decal ink = b.textDecal(plate, "/usr/share/fonts/truetype/dejavu/DejaVuSansCondensed-Bold.ttf",
                          1000.0, Eigen::Vector3f(0.03f, 0.03f, 0.03f), 1.0f, 0.0);
  L.box_decals.push_back(Builder::solidDecal(plate.position, right, Eigen::Vector3d(0, 0, -1),
                                             plate.width + 0.06, 0.11, plate_bg));
  L.box_decals.push_back(ink);
  body.decal_count = 2;
  L.texts.push_back({plate, false});
  Box cabin;
  const double cabin_len = len * uniform(rng, 0.5, 0.6);
  const double cabin_mid = (ylo + yhi) / 2 + uniform(rng, -0.2, 0.2);
  cabin.lo = Eigen::Vector3f(float(cx - wid / 2 + 0.1), float(cabin_mid - cabin_len / 2),
                             float(height * 0.6));
  cabin.hi =
      Eigen::Vector3f(float(cx + wid / 2 - 0.1), float(cabin_mid + cabin_len / 2), float(height));
  cabin.albedo = paint * 0.35f + Eigen::Vector3f(0.04f, 0.05f, 0.06f);
  cabin.material = Material::kCarGlass;
  L.boxes.push_back(body);
  L.boxes.push_back(cabin);
  markOccupancy(body, 1.0f);
}

// Other text ("EXIT", "SLOW", speed limits) on the aisle and cross-aisle floors, each kept
// clear of the arrows and words placed before it.
void LevelBuild::placeFloorWords() {
  const double aw = spec.aisle_width;
  const std::vector<std::string> words = {"EXIT",    "SLOW",       "5 km/h",  "10 km/h", "STOP",
                                          "ONE WAY", "NO PARKING", "EXIT ->", "LIFT"};
  int other_count = 0;
  auto addOther = [&](const Eigen::Vector2d& c, double heading) {
    for (const auto& [centre, radius] : floor_marks)
      if ((centre - c).norm() < radius + 1.2) return;  // would overlap: leave it out
    map::Landmark lm;
    lm.id = fmt::format("{}:other:{}", lv, ++other_count);
    lm.text = pick(rng, words);
    lm.cls = map::TextClass::kOther;
    lm.level = lv;
    lm.surface = map::Surface::kGround;
    lm.heading = heading;
    lm.height = uniform(rng, 0.45, 0.75);
    lm.position = Eigen::Vector3d(c.x(), c.y(), 0.0);
    const bool worn = chance(rng, spec.worn_share);
    Decal d = b.textDecal(
        lm, pick(rng, g.fonts), 250.0, chance(rng, 0.7) ? kWhitePaint : kYellowPaint,
        static_cast<float>(uniform(rng, 0.75, 1.0)), worn ? uniform(rng, 0.2, 0.7) : 0.0);
    if (lm.width > aw - 1.0) {
      g.textures.pop_back();
      lm.height *= (aw - 1.0) / lm.width;
      d = b.textDecal(lm, pick(rng, g.fonts), 250.0, kWhitePaint, 0.9f, 0.0);
    }
    L.floor_decals.push_back(d);
    L.texts.push_back({lm, true, static_cast<int>(L.floor_decals.size()) - 1});
    b.map_landmarks.push_back(lm);
    floor_marks.push_back({c, 0.5 * lm.width});
  };
  for (int aisle = 0; aisle < spec.aisles; ++aisle) {
    const int n = std::uniform_int_distribution<int>(2, 5)(rng);
    for (int i = 0; i < n; ++i) {
      const double x = uniform(rng, g.aisle_x0 + 3.0, g.aisle_x1 - 3.0);
      // Read by a driver going east (up = +x, reading = -y) or west.
      addOther({x, g.aisle_y[aisle] + uniform(rng, -0.8, 0.8)},
               chance(rng, 0.5) ? -M_PI / 2 : M_PI / 2);
    }
  }
  for (double cx : {g.cross_x0, g.cross_x1})
    if (chance(rng, 0.7))
      addOther({cx + uniform(rng, -0.8, 0.8), uniform(rng, 4.0, g.size.y() - 4.0)},
               chance(rng, 0.5) ? 0.0 : M_PI);
}

}  // namespace parkloc::sim::detail
