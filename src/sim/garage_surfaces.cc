#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "sim/garage_builder.h"

namespace parkloc::sim::detail {
namespace {

cv::Point toPaint(const Garage& g, double x, double y) {
  const double s = g.paint_texels_per_metre;
  return {static_cast<int>(std::lround(x * s * 16)), static_cast<int>(std::lround(y * s * 16))};
}

}  // namespace

Decal Builder::textDecal(map::Landmark& lm, const std::string& font, double texels_per_metre,
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

map::Landmark verticalText(const std::string& id, const std::string& text, map::TextClass cls,
                           const std::string& level, const Eigen::Vector3d& n,
                           const Eigen::Vector3d& centre, double height) {
  map::Landmark lm;
  lm.id = id;
  lm.text = text;
  lm.cls = cls;
  lm.level = level;
  lm.surface = map::Surface::kVertical;
  lm.normal = n;
  const Eigen::Vector3d right = (-n).cross(Eigen::Vector3d::UnitZ());
  lm.heading = std::atan2(right.y(), right.x());
  lm.position = centre;
  lm.height = height;
  return lm;
}

Decal Builder::solidDecal(const Eigen::Vector3d& center, const Eigen::Vector3d& axis_u,
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

void LevelBuild::markOccupancy(const Box& box, float strength) {
  cv::rectangle(occupancy_mask, cv::Point(int(box.lo.x() * 10), int(box.lo.y() * 10)),
                cv::Point(int(box.hi.x() * 10), int(box.hi.y() * 10)), cv::Scalar(strength), -1);
}

void paintRect(const Garage& g, cv::Mat& canvas, double x0, double y0, double x1, double y1) {
  cv::rectangle(canvas, toPaint(g, x0, y0), toPaint(g, x1, y1), cv::Scalar(255), -1, cv::LINE_AA,
                4);
}

// An arrow pointing along `dir` (unit, axis-aligned or not) centred at
// c, 2.4 m long.
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

// Tiling concrete: octaves of blurred noise on a torus (blur a 3x3 tiling,
// keep the centre).
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

// Floor shade: large-scale mottling, oil stains in slots, tyre marks,
// occlusion near boxes.
cv::Mat LevelBuild::floorShade() { return detail::floorShade(g, rng, L.slots, occupancy_mask); }

cv::Mat floorShade(const Garage& g, Rng& rng, const std::vector<Slot>& slots,
                   const cv::Mat& occupancy_mask) {
  const double sp = g.shade_texels_per_metre;
  const int sw_px = static_cast<int>(std::ceil(g.size.x() * sp)),
            sh_px = static_cast<int>(std::ceil(g.size.y() * sp));
  cv::Mat shade(sh_px, sw_px, CV_32F);
  cv::RNG(rng()).fill(shade, cv::RNG::NORMAL, 0.0,
                      1.0);  // seeded, not cv::theRNG()
  cv::GaussianBlur(shade, shade, cv::Size(0, 0), 0.8 * sp);
  cv::normalize(shade, shade, -1.0, 1.0, cv::NORM_MINMAX);
  shade = 1.0 + 0.08 * shade;
  cv::Mat marks(sh_px, sw_px, CV_32F, cv::Scalar(0));
  for (const Slot& s : slots) {
    const int blobs = std::uniform_int_distribution<int>(0, 3)(rng);
    for (int i = 0; i < blobs; ++i) {
      const cv::Point c(int((s.center.x() + uniform(rng, -0.6, 0.6)) * sp),
                        int((s.center.y() + uniform(rng, -1.5, 1.5)) * sp));
      cv::ellipse(
          marks, c, cv::Size(int(uniform(rng, 0.1, 0.4) * sp), int(uniform(rng, 0.1, 0.5) * sp)),
          uniform(rng, 0, 180), 0, 360, cv::Scalar(uniform(rng, 0.15, 0.4)), -1, cv::LINE_AA);
    }
  }
  for (const double aisle_y : g.aisle_y)
    for (double lane : {-0.8, 0.8})
      for (double x = g.cross_x0; x < g.cross_x1;) {
        const double len = uniform(rng, 2.0, 10.0);
        const double y = aisle_y + lane + uniform(rng, -0.3, 0.3);
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
  return shade;
}

}  // namespace parkloc::sim::detail
