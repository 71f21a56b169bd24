#include <algorithm>
#include <cmath>

#include "sim/renderer_impl.h"

namespace parkloc::sim {

// Irradiance on a vertical surface with horizontal normal n at p, from the lit lamps nearby
// and light bounced from the floor.
float Renderer::Impl::verticalLightExact(const Eigen::Vector3f& p, const Eigen::Vector2f& n) const {
  const float H = static_cast<float>(g.ceiling_height);
  float e = 0.8f * light.ambient;
  const float dz = H - p.z();
  for (const Lamp& lamp : lamps_on) {
    const float dx = lamp.center.x() - p.x(), dy = lamp.center.y() - p.y();
    const float r2 = dx * dx + dy * dy;
    if (r2 > 400.0f) continue;
    const float d2 = r2 + dz * dz;
    const float facing = n.x() * dx + n.y() * dy;  // horizontal normal
    if (facing <= 0.0f) continue;
    e += light.lamp_power * facing * dz / (d2 * d2);
  }
  return e + 0.15f * floor_light_grid.at(p.x() * light_tpm, p.y() * light_tpm);
}

// The precomputed maps above, for axis-aligned faces; a little brighter near the ceiling.
float Renderer::Impl::verticalLight(const Eigen::Vector3f& p, const Eigen::Vector3f& n) const {
  const int k = n.x() > 0.5f ? 0 : n.x() < -0.5f ? 1 : n.y() > 0.5f ? 2 : 3;
  const float h = std::clamp(p.z() / static_cast<float>(g.ceiling_height), 0.0f, 1.0f);
  return vertical_grid[k].at(p.x() * kVerticalTpm, p.y() * kVerticalTpm) * (0.8f + 0.5f * h * h);
}

// A parked car's lower box (cars stand along y): wheels on the sides, a dark sill and
// underbody, lamps at the ends.
Eigen::Vector3f Renderer::Impl::carBodyAlbedo(const Box& b, const Eigen::Vector3f& p,
                                              const Eigen::Vector3f& n) {
  const Eigen::Vector3f dark(0.025f, 0.025f, 0.028f);
  if (std::abs(n.x()) > 0.5f) {
    const float wheel_y = std::min(p.y() - b.lo.y(), b.hi.y() - p.y()) - 0.85f;
    const float dz = p.z() - 0.32f;
    const float r2 = wheel_y * wheel_y + dz * dz;
    if (r2 < 0.17f * 0.17f) return Eigen::Vector3f(0.35f, 0.35f, 0.36f);  // rim
    if (r2 < 0.32f * 0.32f) return dark;                                  // tyre
    if (r2 < 0.36f * 0.36f) return 0.15f * b.albedo + dark;               // wheel arch
    if (p.z() < 0.2f) return dark;
    if (p.z() < 0.28f) return 0.5f * b.albedo;
    return b.albedo;
  }
  if (std::abs(n.y()) > 0.5f) {
    if (p.z() < 0.2f) return dark;
    const float from_side = std::min(p.x() - b.lo.x(), b.hi.x() - p.x());
    if (p.z() > 0.62f && p.z() < 0.74f && from_side > 0.08f && from_side < 0.38f)
      return (b.lo.y() + b.hi.y() < 2.0f * p.y()) ? Eigen::Vector3f(0.75f, 0.08f, 0.05f)
                                                  : Eigen::Vector3f(0.9f, 0.9f, 0.85f);
    return p.z() < 0.3f ? 0.4f * b.albedo + dark : b.albedo;
  }
  return b.albedo;
}

// Shading of a box face hit at p (ray d, axis of the face hit_axis).
Eigen::Vector3f Renderer::Impl::boxAlbedo(const Box& b, const Eigen::Vector3f& p,
                                          const Eigen::Vector3f& d, const Eigen::Vector3f& n,
                                          float footprint) const {
  const float ctpm = static_cast<float>(g.concrete_texels_per_metre);
  Eigen::Vector3f albedo = b.albedo;
  if (b.material == Material::kPillar) {
    // Painted foot band and concrete grain.
    const float c = g.concrete.sampleNearestLevel(p.x() * ctpm + p.z() * 37.0f,
                                                  p.y() * ctpm + p.z() * ctpm, footprint * ctpm);
    albedo *= 0.6f + 0.7f * c;
    if (p.z() < 0.35f)
      albedo = (static_cast<int>((p.x() + p.y() + p.z()) * 4.0f) & 1)
                   ? Eigen::Vector3f(0.8f, 0.65f, 0.05f)
                   : Eigen::Vector3f(0.06f, 0.06f, 0.06f);
  } else if (b.material == Material::kCarBody) {
    albedo = carBodyAlbedo(b, p, n);
  } else if (b.material == Material::kCarGlass && n.z() == 0.0f) {
    albedo = Eigen::Vector3f(0.05f, 0.06f, 0.07f) +
             0.15f * Eigen::Vector3f(0.5f, 0.5f, 0.5f) * std::abs(d.z());
  }
  for (int k = 0; k < b.decal_count; ++k) {
    const Decal& dc = L.box_decals[b.first_decal + k];
    const Eigen::Vector3f& dn = box_decal_normals[b.first_decal + k];
    if (std::abs((p - dc.origin).dot(dn)) > 2e-3f) continue;
    const float a =
        decalCoverage(dc, p, footprint / std::max(0.2f, std::abs(d.dot(n)))) * dc.opacity;
    if (a > 0.0f) albedo += a * (dc.color - albedo);
  }
  return albedo;
}

// Albedo and irradiance of a pixel on a box, the ceiling or a wall.
void Renderer::Impl::shadeOther(const PixelHit& h, Eigen::Vector3f& albedo, float& e) const {
  const Eigen::Vector3f& p = h.p;
  const Eigen::Vector3f& d = h.d;
  if (h.surface == Surface::kEgo) {
    // Dark paint lit by the floor around the car; its shape is not modelled further.
    albedo = Eigen::Vector3f(0.16f, 0.17f, 0.19f);
    e = 0.6f * floor_light_grid.at(p.x() * light_tpm, p.y() * light_tpm);
  } else if (h.surface == Surface::kBox) {
    Eigen::Vector3f n = Eigen::Vector3f::Zero();
    n[h.axis] = d[h.axis] > 0 ? -1.0f : 1.0f;
    albedo = boxAlbedo(L.boxes[static_cast<size_t>(h.box)], p, d, n, h.footprint);
    e = n.z() > 0.5f ? floor_light_grid.at(p.x() * light_tpm, p.y() * light_tpm) * 0.9f
                     : (n.z() < -0.5f ? 0.3f * light.ambient : verticalLight(p, n));
  } else if (h.surface == Surface::kCeiling) {
    // Ceiling with its lamps.
    albedo = Eigen::Vector3f(0.55f, 0.55f, 0.53f);
    e = ceiling_light_grid.at(p.x() * light_tpm, p.y() * light_tpm);
    const size_t cell = cellIndex(p.x(), p.y());
    for (const int* li = lamp_grid.begin(cell); li != lamp_grid.end(cell); ++li) {
      const Lamp& l = L.lamps[static_cast<size_t>(*li)];
      if (std::abs(p.x() - l.center.x()) <= l.half_size.x() &&
          std::abs(p.y() - l.center.y()) <= l.half_size.y()) {
        albedo = Eigen::Vector3f(1.0f, 1.0f, 0.97f);
        e = lamp_is_on[static_cast<size_t>(*li)] ? 2.5f : 0.25f;
      }
    }
  } else {
    // Walls: paint with a coloured band at the bottom.
    const float ctpm = static_cast<float>(g.concrete_texels_per_metre);
    Eigen::Vector3f n = Eigen::Vector3f::Zero();
    n[h.axis] = d[h.axis] > 0 ? -1.0f : 1.0f;
    const float c =
        g.concrete.sampleNearestLevel((p.x() + p.y()) * ctpm, p.z() * ctpm, h.footprint * ctpm);
    albedo = (p.z() < g.wall_band_height ? g.wall_band : g.wall_albedo) * (0.8f + 0.4f * c);
    e = verticalLight(p, n);
  }
}

}  // namespace parkloc::sim
