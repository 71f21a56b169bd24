#include "sim/garage.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <random>

#include "common/error.h"
#include "sim/text_raster.h"

namespace parkloc::sim {
namespace {

using Rng = std::mt19937_64;

double uniform(Rng& rng, double a, double b) {
  return std::uniform_real_distribution<double>(a, b)(rng);
}
bool chance(Rng& rng, double p) { return uniform(rng, 0.0, 1.0) < p; }
template <typename T>
const T& pick(Rng& rng, const std::vector<T>& v) {
  return v[std::uniform_int_distribution<size_t>(0, v.size() - 1)(rng)];
}

const Eigen::Vector3f kWhitePaint(0.88f, 0.88f, 0.85f);
const Eigen::Vector3f kYellowPaint(0.90f, 0.72f, 0.12f);

// Tiling concrete: octaves of blurred noise on a torus (blur a 3x3 tiling, keep the centre).
cv::Mat makeConcrete(Rng& rng, int size) {
  cv::Mat acc(size, size, CV_32F, cv::Scalar(0));
  std::normal_distribution<float> gauss(0.0f, 1.0f);
  const std::pair<double, double> octaves[] = {{0.7, 0.25}, {2.5, 0.3}, {10.0, 0.3}, {40.0, 0.35}};
  for (const auto& [sigma, weight] : octaves) {
    cv::Mat n(size, size, CV_32F);
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) n.at<float>(y, x) = gauss(rng);
    cv::Mat tiled;
    cv::repeat(n, 3, 3, tiled);
    cv::GaussianBlur(tiled, tiled, cv::Size(0, 0), sigma);
    cv::Mat centre = tiled(cv::Rect(size, size, size, size));
    cv::Scalar mean, stddev;
    cv::meanStdDev(centre, mean, stddev);
    acc += (centre - mean[0]) * (weight / std::max(1e-6, stddev[0]));
  }
  cv::Mat out;
  acc.convertTo(out, CV_8U, 22.0, 150.0);
  // Sparse light aggregate specks.
  std::uniform_int_distribution<int> pos(0, size - 1);
  for (int i = 0; i < size * size / 800; ++i)
    out.at<uint8_t>(pos(rng), pos(rng)) = static_cast<uint8_t>(175 + pos(rng) % 30);
  return out;
}

struct Builder {
  const GarageSpec& spec;
  Garage& g;
  Rng& rng;
  TextRasterizer raster;
  std::vector<map::Landmark> map_landmarks;

  // Adds a text decal whose ink box is the landmark's corners; fills width/height.
  Decal textDecal(map::Landmark& lm, const std::string& font, double texels_per_metre,
                  const Eigen::Vector3f& color, float opacity, double wear) {
    const int ink_px = std::max(8, static_cast<int>(std::lround(lm.height * texels_per_metre)));
    cv::Mat ink = raster.render(font, lm.text, ink_px);
    const double tpm = ink.rows / lm.height;  // exact: the ink box is lm.height tall
    lm.width = ink.cols / tpm;
    const double ink_before = cv::sum(ink)[0];
    if (wear > 0.0) wearInk(ink, wear, rng);
    const double ink_after = cv::sum(ink)[0];
    const int pad = 6;
    g.textures.emplace_back(padInk(ink, pad));
    Decal d;
    const auto c = lm.corners();
    d.origin = c[0].cast<float>();
    d.axis_u = lm.readingDirection().cast<float>();
    d.axis_v = (-lm.upDirection()).cast<float>();
    d.size_u = static_cast<float>(lm.width);
    d.size_v = static_cast<float>(lm.height);
    d.texels_per_metre = static_cast<float>(tpm);
    d.pad = pad;
    d.texture = static_cast<int>(g.textures.size()) - 1;
    d.color = color;
    d.opacity = opacity;
    d.wear = static_cast<float>(wear);
    d.ink_kept = ink_before > 0.0 ? static_cast<float>(ink_after / ink_before) : 1.0f;
    return d;
  }

  // A solid rectangle centred on `center` with the given axes (plate backgrounds, pillar bands).
  static Decal solidDecal(const Eigen::Vector3d& center, const Eigen::Vector3d& axis_u,
                          const Eigen::Vector3d& axis_v, double w, double h,
                          const Eigen::Vector3f& color) {
    Decal d;
    d.origin = (center - 0.5 * w * axis_u - 0.5 * h * axis_v).cast<float>();
    d.axis_u = axis_u.cast<float>();
    d.axis_v = axis_v.cast<float>();
    d.size_u = static_cast<float>(w);
    d.size_v = static_cast<float>(h);
    d.color = color;
    return d;
  }
};

cv::Point toPaint(const Garage& g, double x, double y) {
  const double s = g.paint_texels_per_metre;
  return {static_cast<int>(std::lround(x * s * 16)), static_cast<int>(std::lround(y * s * 16))};
}

void paintRect(const Garage& g, cv::Mat& canvas, double x0, double y0, double x1, double y1) {
  cv::rectangle(canvas, toPaint(g, x0, y0), toPaint(g, x1, y1), cv::Scalar(255), -1, cv::LINE_AA,
                4);
}

// An arrow pointing along `dir` (unit, axis-aligned or not) centred at c, 2.4 m long.
void paintArrow(const Garage& g, cv::Mat& canvas, const Eigen::Vector2d& c,
                const Eigen::Vector2d& dir) {
  const Eigen::Vector2d n(-dir.y(), dir.x());
  const std::vector<std::pair<double, double>> shape = {
      {-1.2, -0.12}, {0.4, -0.12}, {0.4, -0.4}, {1.2, 0.0}, {0.4, 0.4}, {0.4, 0.12}, {-1.2, 0.12}};
  std::vector<cv::Point> pts;
  for (const auto& [a, b] : shape) {
    const Eigen::Vector2d p = c + a * dir + b * n;
    pts.push_back(toPaint(g, p.x(), p.y()));
  }
  cv::fillPoly(canvas, std::vector<std::vector<cv::Point>>{pts}, cv::Scalar(255), cv::LINE_AA, 4);
}

std::string randomPlate(Rng& rng) {
  const std::string letters = "ABCDEFGHKLMNPRSTUVWXYZ";
  auto letter = [&] {
    return letters[std::uniform_int_distribution<size_t>(0, letters.size() - 1)(rng)];
  };
  std::string s;
  s += letter();
  if (chance(rng, 0.6)) s += letter();
  s += "-";
  s += letter();
  s += letter();
  s += " ";
  s += std::to_string(std::uniform_int_distribution<int>(10, 9999)(rng));
  return s;
}

void buildLevel(Builder& b, int level_index) {
  const GarageSpec& spec = b.spec;
  Garage& g = b.g;
  Rng& rng = b.rng;
  GarageLevel& L = g.levels[level_index];
  const std::string& lv = L.name;
  const double aw = spec.aisle_width, depth = spec.slot_depth, sw = spec.slot_width;
  const double pillar_gap = spec.pillar_size + 0.1;
  const double H = g.ceiling_height;

  const bool yellow_numbers = chance(rng, spec.yellow_share);
  const Eigen::Vector3f number_color = yellow_numbers ? kYellowPaint : kWhitePaint;
  const bool yellow_lines = chance(rng, 0.35);
  const int pillar_style = std::uniform_int_distribution<int>(0, 3)(rng);
  const Eigen::Vector3f pillar_band = pick(rng, std::vector<Eigen::Vector3f>{{0.9f, 0.75f, 0.1f},
                                                                             {0.85f, 0.85f, 0.82f},
                                                                             {0.2f, 0.45f, 0.8f},
                                                                             {0.85f, 0.3f, 0.2f},
                                                                             {0.3f, 0.65f, 0.35f}});
  const Eigen::Vector3f pillar_ink = pillar_band.sum() > 1.6f
                                         ? Eigen::Vector3f(0.05f, 0.05f, 0.06f)
                                         : Eigen::Vector3f(0.95f, 0.95f, 0.95f);

  const int paint_w = static_cast<int>(std::ceil(g.size.x() * g.paint_texels_per_metre));
  const int paint_h = static_cast<int>(std::ceil(g.size.y() * g.paint_texels_per_metre));
  cv::Mat white(paint_h, paint_w, CV_8UC1, cv::Scalar(0));
  cv::Mat yellow(paint_h, paint_w, CV_8UC1, cv::Scalar(0));
  cv::Mat& lines = yellow_lines ? yellow : white;
  const double lw = 0.12;  // line width

  cv::Mat occupancy_mask(static_cast<int>(g.size.y() * 10), static_cast<int>(g.size.x() * 10),
                         CV_32F, cv::Scalar(0));
  auto markOccupancy = [&](const Box& box, float strength) {
    cv::rectangle(occupancy_mask, cv::Point(int(box.lo.x() * 10), int(box.lo.y() * 10)),
                  cv::Point(int(box.hi.x() * 10), int(box.hi.y() * 10)), cv::Scalar(strength), -1);
  };

  // Arrows and floor words placed so far (centre, radius): new ones keep clear of them.
  std::vector<std::pair<Eigen::Vector2d, double>> floor_marks;
  int number_index = 0;
  int pillar_count = 0, plate_count = 0;
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
          // Pillar in the gap, its aisle face 0.3 m inside the row.
          const double px = x + pillar_gap / 2;
          const double ps = spec.pillar_size;
          const double py_near = y_edge + side * 0.3;
          Box p;
          p.lo = Eigen::Vector3f(float(px - ps / 2), float(std::min(py_near, py_near + side * ps)),
                                 0.0f);
          p.hi = Eigen::Vector3f(float(px + ps / 2), float(std::max(py_near, py_near + side * ps)),
                                 float(H));
          p.albedo = Eigen::Vector3f(0.62f, 0.62f, 0.6f);
          p.material = Material::kPillar;
          p.first_decal = static_cast<int>(L.box_decals.size());
          ++column;
          ++pillar_count;
          std::string text;
          switch (pillar_style) {
            case 0:
              text = lv;
              break;
            case 1:
              text = fmt::format("{}-{}", zone, column);
              break;
            case 2:
              text = fmt::format("{}-{}{}", lv, zone, column);
              break;
            default:
              text = fmt::format("{}{}", zone, column);
              break;
          }
          const double text_h = uniform(rng, 0.2, 0.3);
          const double text_z = uniform(rng, 1.3, 1.7);
          const std::string font = pick(rng, g.fonts);
          // Text on the aisle face and both faces along the aisle.
          const Eigen::Vector3d centre(px, py_near + side * ps / 2, 0.0);
          const std::pair<Eigen::Vector3d, const char*> faces[] = {
              {Eigen::Vector3d(0, -side, 0), "aisle"},
              {Eigen::Vector3d(1, 0, 0), "east"},
              {Eigen::Vector3d(-1, 0, 0), "west"}};
          for (const auto& [n, face_name] : faces) {
            map::Landmark lm;
            lm.id = fmt::format("{}:pillar:{}:{}", lv, pillar_count, face_name);
            lm.text = text;
            lm.cls = map::TextClass::kPillar;
            lm.level = lv;
            lm.surface = map::Surface::kVertical;
            lm.normal = n;
            const Eigen::Vector3d right = (-n).cross(Eigen::Vector3d::UnitZ());
            lm.heading = std::atan2(right.y(), right.x());
            lm.position = centre + n * (ps / 2) + Eigen::Vector3d(0, 0, text_z);
            lm.height = text_h;
            Decal ink = b.textDecal(lm, font, 600.0, pillar_ink, 1.0f, 0.0);
            if (lm.width > ps - 0.06) {  // too wide for the face: shrink
              lm.height *= (ps - 0.06) / lm.width;
              g.textures.pop_back();
              ink = b.textDecal(lm, font, 600.0, pillar_ink, 1.0f, 0.0);
            }
            const Eigen::Vector3d down(0, 0, -1);
            L.box_decals.push_back(Builder::solidDecal(lm.position, right, down, ps * 0.999,
                                                       lm.height + 0.16, pillar_band));
            L.box_decals.push_back(ink);
            L.texts.push_back({lm, true});
            b.map_landmarks.push_back(lm);
          }
          p.decal_count = static_cast<int>(L.box_decals.size()) - p.first_decal;
          L.boxes.push_back(p);
          markOccupancy(p, 1.0f);
          x += pillar_gap;
        }
        // Slot k spans [x, x + sw].
        Slot slot;
        slot.center = Eigen::Vector2d(x + sw / 2, y_edge + side * depth / 2);
        slot.aisle = aisle;
        slot.side = side;
        slot.number =
            formatParkingNumber(spec.numbering, lv, spec.first_number + number_index, zone);
        if (spec.numbering == NumberingScheme::kZoneLetter)
          slot.number = formatParkingNumber(spec.numbering, lv, spec.first_number + k, zone);
        ++number_index;
        paintRect(g, lines, x + sw - lw / 2, std::min(y_edge, y_edge + side * depth),
                  x + sw + lw / 2, std::max(y_edge, y_edge + side * depth));

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

        // A parked car in a share of the slots.
        slot.occupied = chance(rng, spec.occupancy);
        if (slot.occupied) {
          const double len = uniform(rng, 4.1, 4.9), wid = uniform(rng, 1.7, 1.9);
          const double height = uniform(rng, 1.4, 1.65);
          const double back_gap = uniform(rng, 0.15, 0.9);
          const double cx = x + sw / 2 + uniform(rng, -0.15, 0.15);
          const double y_back = y_edge + side * depth;
          const double y_far = y_back - side * back_gap;  // end at the back of the slot
          const double y_near = y_far - side * len;       // end facing the aisle
          const double ylo = std::min(y_far, y_near), yhi = std::max(y_far, y_near);
          const Eigen::Vector3f paint =
              pick(rng, std::vector<Eigen::Vector3f>{{0.85f, 0.85f, 0.85f},
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
          const Eigen::Vector3f plate_bg = yellow_plate ? Eigen::Vector3f(0.85f, 0.7f, 0.1f)
                                                        : Eigen::Vector3f(0.88f, 0.88f, 0.88f);
          Decal ink =
              b.textDecal(plate, "/usr/share/fonts/truetype/dejavu/DejaVuSansCondensed-Bold.ttf",
                          1000.0, Eigen::Vector3f(0.03f, 0.03f, 0.03f), 1.0f, 0.0);
          L.box_decals.push_back(Builder::solidDecal(plate.position, right,
                                                     Eigen::Vector3d(0, 0, -1), plate.width + 0.06,
                                                     0.11, plate_bg));
          L.box_decals.push_back(ink);
          body.decal_count = 2;
          L.texts.push_back({plate, false});
          Box cabin;
          const double cabin_len = len * uniform(rng, 0.5, 0.6);
          const double cabin_mid = (ylo + yhi) / 2 + uniform(rng, -0.2, 0.2);
          cabin.lo = Eigen::Vector3f(float(cx - wid / 2 + 0.1), float(cabin_mid - cabin_len / 2),
                                     float(height * 0.6));
          cabin.hi = Eigen::Vector3f(float(cx + wid / 2 - 0.1), float(cabin_mid + cabin_len / 2),
                                     float(height));
          cabin.albedo = paint * 0.35f + Eigen::Vector3f(0.04f, 0.05f, 0.06f);
          cabin.material = Material::kCarGlass;
          L.boxes.push_back(body);
          L.boxes.push_back(cabin);
          markOccupancy(body, 1.0f);
        }
        L.slots.push_back(slot);
        x += sw;
      }
      paintRect(g, lines, x - lw / 2, std::min(y_edge, y_edge + side * depth), x + lw / 2,
                std::max(y_edge, y_edge + side * depth));
      // Edge line between row and aisle on some garages.
      if (yellow_lines) paintRect(g, lines, g.aisle_x0, y_edge - lw / 2, x, y_edge + lw / 2);
    }
    // Direction arrows and other text in the aisle.
    for (double ax = g.aisle_x0 + uniform(rng, 3.0, 8.0); ax < g.aisle_x1 - 3.0;
         ax += uniform(rng, 12.0, 20.0)) {
      const Eigen::Vector2d c(ax, yc + (chance(rng, 0.5) ? 1.4 : -1.4));
      paintArrow(g, white, c, chance(rng, 0.5) ? Eigen::Vector2d(1, 0) : Eigen::Vector2d(-1, 0));
      floor_marks.push_back({c, 1.3});
    }
  }

  // Other text ("EXIT", "SLOW", speed limits) on the aisle and cross-aisle floors.
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

  L.paint_white = MipTexture(white);
  L.paint_yellow = MipTexture(yellow);

  // Lamps: tubes along the aisles and cross aisles every ~5 m, sparser over the slot rows.
  for (int aisle = 0; aisle < spec.aisles; ++aisle)
    for (double x = g.aisle_x0 + 1.5; x < g.aisle_x1; x += 5.0)
      L.lamps.push_back(
          {Eigen::Vector2f(float(x), float(g.aisle_y[aisle])), Eigen::Vector2f(0.6f, 0.07f)});
  for (double cx : {g.cross_x0, g.cross_x1})
    for (double y = 3.0; y < g.size.y() - 1.0; y += 5.5)
      L.lamps.push_back({Eigen::Vector2f(float(cx), float(y)), Eigen::Vector2f(0.07f, 0.6f)});

  // Floor shade: large-scale mottling, oil stains in slots, tyre marks, occlusion near boxes.
  const double sp = g.shade_texels_per_metre;
  const int sw_px = static_cast<int>(std::ceil(g.size.x() * sp)),
            sh_px = static_cast<int>(std::ceil(g.size.y() * sp));
  cv::Mat shade(sh_px, sw_px, CV_32F);
  cv::RNG(rng()).fill(shade, cv::RNG::NORMAL, 0.0, 1.0);  // seeded, not cv::theRNG()
  cv::GaussianBlur(shade, shade, cv::Size(0, 0), 0.8 * sp);
  cv::normalize(shade, shade, -1.0, 1.0, cv::NORM_MINMAX);
  shade = 1.0 + 0.08 * shade;
  cv::Mat marks(sh_px, sw_px, CV_32F, cv::Scalar(0));
  for (const Slot& s : L.slots) {
    const int blobs = std::uniform_int_distribution<int>(0, 3)(rng);
    for (int i = 0; i < blobs; ++i) {
      const cv::Point c(int((s.center.x() + uniform(rng, -0.6, 0.6)) * sp),
                        int((s.center.y() + uniform(rng, -1.5, 1.5)) * sp));
      cv::ellipse(
          marks, c, cv::Size(int(uniform(rng, 0.1, 0.4) * sp), int(uniform(rng, 0.1, 0.5) * sp)),
          uniform(rng, 0, 180), 0, 360, cv::Scalar(uniform(rng, 0.15, 0.4)), -1, cv::LINE_AA);
    }
  }
  for (int aisle = 0; aisle < spec.aisles; ++aisle)
    for (double lane : {-0.8, 0.8})
      for (double x = g.cross_x0; x < g.cross_x1;) {
        const double len = uniform(rng, 2.0, 10.0);
        const double y = g.aisle_y[aisle] + lane + uniform(rng, -0.3, 0.3);
        cv::line(marks, cv::Point(int(x * sp), int(y * sp)),
                 cv::Point(int((x + len) * sp), int((y + uniform(rng, -0.3, 0.3)) * sp)),
                 cv::Scalar(uniform(rng, 0.08, 0.2)), std::max(1, int(0.2 * sp)), cv::LINE_AA);
        x += len + uniform(rng, 1.0, 8.0);
      }
  cv::GaussianBlur(marks, marks, cv::Size(0, 0), 1.0);
  shade = shade.mul(1.0 - marks);
  cv::Mat occlusion;
  cv::resize(occupancy_mask, occlusion, shade.size(), 0, 0, cv::INTER_AREA);
  cv::GaussianBlur(occlusion, occlusion, cv::Size(0, 0), 0.35 * sp);
  shade = shade.mul(1.0 - 0.6 * cv::min(occlusion, 1.0));
  L.floor_shade = shade;
}

}  // namespace

int Garage::levelIndex(const std::string& name) const {
  for (size_t i = 0; i < levels.size(); ++i)
    if (levels[i].name == name) return static_cast<int>(i);
  return -1;
}

std::string formatParkingNumber(NumberingScheme scheme, const std::string& level, int number,
                                int zone) {
  switch (scheme) {
    case NumberingScheme::kThreeDigit:
      return fmt::format("{:03d}", number);
    case NumberingScheme::kPlain:
      return std::to_string(number);
    case NumberingScheme::kLevelDash:
      return fmt::format("{}-{:03d}", level, number);
    case NumberingScheme::kZoneLetter:
      return fmt::format("{}{:03d}", static_cast<char>(zone), number);
  }
  return std::to_string(number);
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
