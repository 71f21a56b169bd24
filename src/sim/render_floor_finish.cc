#include <algorithm>
#include <cmath>

#include "sim/floor_finish.h"
#include "sim/renderer_impl.h"

namespace parkloc::sim {

// Radiance of the lit lamps mirrored at ceiling point q. A rough mirror spreads each lamp's
// image by `blur_m` across the plane of incidence and by `blur_along_m` along it (`along`: the
// view's horizontal direction): at grazing view the spread stretches toward the camera into the
// long streaks a wet floor shows.
float Renderer::Impl::mirroredLamps(const Eigen::Vector2f& q, const Eigen::Vector2f& along,
                                    float blur_m, float blur_along_m) const {
  // A lamp's tube is far brighter than the 2.5 its clipped pixels show (shadeOther): its
  // mirror image stays near white even at a few percent reflectance.
  constexpr float kLampRadiance = 8.0f;
  const float reach = blur_along_m + 0.7f;
  const Eigen::Vector2f across(-along.y(), along.x());
  int seen[32];
  int seen_count = 0;
  float sum = 0.0f;
  for (float cy = std::floor(q.y() - reach); cy <= q.y() + reach; cy += 1.0f)
    for (float cx = std::floor(q.x() - reach); cx <= q.x() + reach; cx += 1.0f) {
      if (cx < 0.0f || cy < 0.0f || cx >= static_cast<float>(grid_w) ||
          cy >= static_cast<float>(grid_h))
        continue;
      const size_t cell = cellIndex(cx, cy);
      for (const int* li = lamp_grid.begin(cell); li != lamp_grid.end(cell); ++li) {
        if (!lamp_is_on[static_cast<size_t>(*li)]) continue;
        if (std::find(seen, seen + seen_count, *li) != seen + seen_count) continue;
        if (seen_count < 32) seen[seen_count++] = *li;
        const Lamp& l = L.lamps[static_cast<size_t>(*li)];
        const Eigen::Vector2f d = q - l.center;
        // The lamp's extent along and across the view, and q's offsets from its centre.
        const float ha =
            std::abs(l.half_size.x() * along.x()) + std::abs(l.half_size.y() * along.y());
        const float hc =
            std::abs(l.half_size.x() * across.x()) + std::abs(l.half_size.y() * across.y());
        const float da = std::abs(d.dot(along)), dc = std::abs(d.dot(across));
        // A box blurred by a ramp of the blur's width on each edge.
        const float wa = std::max(0.01f, blur_along_m), wc = std::max(0.01f, blur_m);
        const float cover_a = std::clamp((ha + wa - da) / (2.0f * wa), 0.0f, 1.0f);
        const float cover_c = std::clamp((hc + wc - dc) / (2.0f * wc), 0.0f, 1.0f);
        const float spread = (ha * hc) / ((ha + wa) * (hc + wc));
        sum += kLampRadiance * cover_a * cover_c * std::sqrt(spread);
      }
    }
  return sum;
}

void Renderer::Impl::shadeFloorFinish(const PixelHit* hits, const int* pixels, int count,
                                      Eigen::Vector3f* albedo, const float* irradiance) const {
  const float gtpm = static_cast<float>(g.grime_texels_per_metre);
  const float wtpm = static_cast<float>(g.wetness_texels_per_metre);
  const float H = static_cast<float>(g.ceiling_height);
  for (int k = 0; k < count; ++k) {
    const int x = pixels[k];
    const PixelHit& h = hits[x];
    Eigen::Vector3f a = albedo[x];
    // Tyre rubber, oil and cracks lie over the paint as over the concrete.
    if (grime_grid.data) a *= grime_grid.at(h.p.x() * gtpm - 0.5f, h.p.y() * gtpm - 0.5f);
    if (g.gloss > 0.0f && h.d.z() < 0.0f) {
      const float wet = wetness_grid.data ? wetness_grid.at(h.p.x() * wtpm, h.p.y() * wtpm) : 0.0f;
      // Water darkens concrete (it fills the pores that scatter light).
      a *= 1.0f - 0.3f * wet * g.gloss;
      // The mirrored ray meets the ceiling at q; the path from the floor to q spreads the
      // lamp's image by the surface's roughness, less where a puddle lies.
      const float cos_i = -h.d.z();
      const float t = H / std::max(0.05f, cos_i);
      const Eigen::Vector2f q(h.p.x() + t * h.d.x(), h.p.y() + t * h.d.y());
      const float roughness = 0.05f - 0.04f * wet;
      const float blur = 0.02f + roughness * t + h.footprint;
      const Eigen::Vector2f along = Eigen::Vector2f(h.d.x(), h.d.y()).normalized();
      const float reflect = fresnelSchlick(cos_i) * g.gloss * (0.35f + 0.65f * wet);
      const float ceiling = 0.3f * ceiling_light_grid.at(q.x() * light_tpm, q.y() * light_tpm);
      const float radiance =
          reflect * (mirroredLamps(q, along, blur, blur / std::max(0.1f, cos_i)) + ceiling);
      a += Eigen::Vector3f::Constant(radiance / std::max(0.02f, irradiance[x]));
    }
    albedo[x] = a;
  }
}

}  // namespace parkloc::sim
