#include "sim/renderer.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <opencv2/core/utility.hpp>
#include <random>

#include "sim/renderer_impl.h"

namespace parkloc::sim {

using detail::kInf;

Renderer::Impl::Impl(const Garage& garage, const GarageLevel& level, const geometry::Rig& r,
                     std::shared_ptr<const std::vector<CameraRays>> ry, const LightingOptions& li)
    : g(garage), L(level), rig(r), rays(std::move(ry)), light(li) {
  std::mt19937_64 rng(light.lamp_seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (const Lamp& lamp : L.lamps) {
    const bool on = uni(rng) < light.lamps_on_share;
    lamp_is_on.push_back(on);
    if (on) lamps_on.push_back(lamp);
  }
  const float H = static_cast<float>(g.ceiling_height);
  const int lw = static_cast<int>(std::ceil(g.size.x() * light_tpm)) + 1;
  const int lh = static_cast<int>(std::ceil(g.size.y() * light_tpm)) + 1;
  floor_light.create(lh, lw, CV_32F);
  ceiling_light.create(lh, lw, CV_32F);
  cv::parallel_for_(cv::Range(0, lh), [&](const cv::Range& range) {
    for (int y = range.start; y < range.end; ++y)
      for (int x = 0; x < lw; ++x) {
        const float px = x / light_tpm, py = y / light_tpm;
        float e = light.ambient, c = 0.6f * light.ambient;
        for (const Lamp& lamp : lamps_on) {
          const float dx = px - lamp.center.x(), dy = py - lamp.center.y();
          const float d2 = dx * dx + dy * dy + H * H;
          e += light.lamp_power * H * H / (d2 * d2);  // cosine at lamp and floor
          const float r2 = dx * dx + dy * dy;
          c += 0.5f * light.lamp_power / (H * H) *
               (0.15f / (0.15f + r2) + 0.2f / (1.0f + 0.3f * r2));
        }
        floor_light.at<float>(y, x) = e;
        ceiling_light.at<float>(y, x) = c;
      }
  });
  floor_light_grid = FloatGrid(floor_light);
  ceiling_light_grid = FloatGrid(ceiling_light);
  floor_shade_grid = FloatGrid(L.floor_shade);
  if (!L.floor_grime.empty()) grime_grid = FloatGrid(L.floor_grime);
  if (!L.floor_wetness.empty()) wetness_grid = FloatGrid(L.floor_wetness);
  floor_finish = !L.floor_grime.empty() || g.gloss > 0.0f;
  const int vw = static_cast<int>(std::ceil(g.size.x() * kVerticalTpm)) + 1;
  const int vh = static_cast<int>(std::ceil(g.size.y() * kVerticalTpm)) + 1;
  const Eigen::Vector2f normals[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (int k = 0; k < 4; ++k) {
    vertical_light[k].create(vh, vw, CV_32F);
    for (int y = 0; y < vh; ++y)
      for (int x = 0; x < vw; ++x)
        vertical_light[k].at<float>(y, x) = verticalLightExact(
            Eigen::Vector3f(x / kVerticalTpm, y / kVerticalTpm, 1.0f), normals[k]);
    vertical_grid[k] = FloatGrid(vertical_light[k]);
  }
  paint_mask_w = static_cast<int>(std::ceil(g.size.x() * 2.0)) + 1;
  paint_mask_h = static_cast<int>(std::ceil(g.size.y() * 2.0)) + 1;
  paint_mask.assign(static_cast<size_t>(paint_mask_w) * paint_mask_h, 0);
  for (const auto* tex : {&L.paint_white, &L.paint_yellow}) {
    const float tpm = static_cast<float>(g.paint_texels_per_metre);
    for (int y = 0; y < tex->height(); y += 2)
      for (int x = 0; x < tex->width(); x += 2) {
        if (tex->sample(float(x), float(y), 1.0f) <= 0.0f) continue;
        const int cx = static_cast<int>(x / tpm * 2.0f), cy = static_cast<int>(y / tpm * 2.0f);
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int mx = std::clamp(cx + dx, 0, paint_mask_w - 1),
                      my = std::clamp(cy + dy, 0, paint_mask_h - 1);
            paint_mask[static_cast<size_t>(my) * paint_mask_w + mx] = 1;
          }
      }
  }
  grid_w = static_cast<int>(std::ceil(g.size.x())) + 1;
  grid_h = static_cast<int>(std::ceil(g.size.y())) + 1;
  std::vector<std::vector<int>> decals_per_cell(static_cast<size_t>(grid_w) * grid_h),
      lamps_per_cell(decals_per_cell.size());
  for (size_t i = 0; i < L.floor_decals.size(); ++i) {
    const Decal& d = L.floor_decals[i];
    const float pad = d.pad / d.texels_per_metre;
    Eigen::Vector2f lo(kInf, kInf), hi(-kInf, -kInf);
    for (float a : {-pad, d.size_u + pad})
      for (float b : {-pad, d.size_v + pad}) {
        const Eigen::Vector3f p = d.origin + a * d.axis_u + b * d.axis_v;
        lo = lo.cwiseMin(p.head<2>());
        hi = hi.cwiseMax(p.head<2>());
      }
    addToGrid(decals_per_cell, lo, hi, static_cast<int>(i));
  }
  for (size_t i = 0; i < L.lamps.size(); ++i) {
    const Lamp& l = L.lamps[i];
    addToGrid(lamps_per_cell, l.center - l.half_size, l.center + l.half_size, static_cast<int>(i));
  }
  paint = MipTexturePair(L.paint_white, L.paint_yellow);
  for (const Decal& d : L.box_decals) box_decal_normals.push_back(d.axis_u.cross(d.axis_v));
  decal_grid.build(decals_per_cell);
  lamp_grid.build(lamps_per_cell);
  for (size_t ci = 0; ci < rig.cameras.size(); ++ci) {
    const CameraRays& cr = rays->at(ci);
    const Eigen::Matrix3f vehicle_from_camera =
        rig.cameras[ci].vehicle_from_camera.linear().cast<float>();
    std::vector<VehicleRay> vr(cr.rays.size());
    for (size_t i = 0; i < vr.size(); ++i) {
      const Eigen::Vector3f& rc = cr.rays[i];
      if (rc.isZero()) {
        vr[i] = {0.0f, 0.0f, 0.0f, 0.0f};
        continue;
      }
      const Eigen::Vector3f rv = vehicle_from_camera * rc;
      vr[i] = {rv.x(), rv.y(), rv.z(), std::max(1e-4f, cr.pixel_angle[i])};
    }
    const auto& body = rig.cameras[ci].body;
    std::vector<uint8_t> ego(body ? vr.size() : 0, 0);
    const Eigen::Vector3d eye = rig.cameras[ci].vehicle_from_camera.translation();
    for (size_t i = 0; i < ego.size(); ++i)
      ego[i] = vr[i].angle > 0.0f &&
               geometry::bodyHitsRay(*body, eye, Eigen::Vector3d(vr[i].x, vr[i].y, vr[i].z));
    vehicle_rays.push_back(std::move(vr));
    ego_masks.push_back(std::move(ego));
  }
  buildToneCurve();
}

void Renderer::Impl::addToGrid(std::vector<std::vector<int>>& grid, const Eigen::Vector2f& lo,
                               const Eigen::Vector2f& hi, int index) const {
  const int x0 = std::clamp(static_cast<int>(std::floor(lo.x())), 0, grid_w - 1);
  const int x1 = std::clamp(static_cast<int>(std::floor(hi.x())), 0, grid_w - 1);
  const int y0 = std::clamp(static_cast<int>(std::floor(lo.y())), 0, grid_h - 1);
  const int y1 = std::clamp(static_cast<int>(std::floor(hi.y())), 0, grid_h - 1);
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) grid[static_cast<size_t>(y) * grid_w + x].push_back(index);
}

Renderer::Renderer(const Garage& garage, int level, const geometry::Rig& rig,
                   std::shared_ptr<const std::vector<CameraRays>> rays,
                   const LightingOptions& light)
    : impl_(std::make_unique<Impl>(garage, garage.levels.at(level), rig, std::move(rays), light)) {}

Renderer::Renderer(const Garage& garage, const GarageLevel& level, const geometry::Rig& rig,
                   std::shared_ptr<const std::vector<CameraRays>> rays,
                   const LightingOptions& light)
    : impl_(std::make_unique<Impl>(garage, level, rig, std::move(rays), light)) {}

Renderer::~Renderer() = default;

const GarageLevel& Renderer::level() const { return impl_->L; }

cv::Mat Renderer::renderCamera(size_t camera, const geometry::Pose2& map_from_vehicle,
                               uint64_t noise_seed) const {
  return impl_->renderCamera(camera, map_from_vehicle, noise_seed);
}

double Renderer::floorInkContrast(size_t camera, const Eigen::Vector2d& pixel, int decal) const {
  return impl_->floorInkContrast(camera, pixel, decal);
}

const LightingOptions& Renderer::light() const { return impl_->light; }

std::vector<cv::Mat> Renderer::render(const geometry::Pose2& map_from_vehicle,
                                      uint64_t noise_seed) const {
  std::vector<cv::Mat> out;
  for (size_t c = 0; c < impl_->rig.cameras.size(); ++c)
    out.push_back(renderCamera(c, map_from_vehicle, noise_seed));
  return out;
}

}  // namespace parkloc::sim
