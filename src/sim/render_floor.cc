#include <algorithm>
#include <cmath>

#include "sim/renderer_impl.h"

namespace parkloc::sim {

// Coverage of decal d at point p (0 outside); footprint in metres.
float Renderer::Impl::decalCoverage(const Decal& d, const Eigen::Vector3f& p,
                                    float footprint_m) const {
  const Eigen::Vector3f q = p - d.origin;
  const float u = q.dot(d.axis_u), v = q.dot(d.axis_v);
  if (d.texture < 0)
    return (u >= 0.0f && v >= 0.0f && u <= d.size_u && v <= d.size_v) ? 1.0f : 0.0f;
  const float pad = d.pad / d.texels_per_metre;
  if (u < -pad || v < -pad || u > d.size_u + pad || v > d.size_v + pad) return 0.0f;
  return g.textures[d.texture].sample(u * d.texels_per_metre + d.pad - 0.5f,
                                      v * d.texels_per_metre + d.pad - 0.5f,
                                      footprint_m * d.texels_per_metre);
}

// Floor albedo without markings (concrete x shade) and irradiance of the listed pixels,
// four at a time where SSE2 is there (the same operations as bareFloorAlbedo).
void Renderer::Impl::shadeFloorBase(const PixelHit* hits, const int* pixels, int count,
                                    Eigen::Vector3f* albedo, float* irradiance) const {
  int k = 0;
#if defined(__SSE2__)
  if (floor_shade_grid.vectorizable() && floor_light_grid.vectorizable()) {
    const float ctpm = static_cast<float>(g.concrete_texels_per_metre);
    const float stpm = static_cast<float>(g.shade_texels_per_metre);
    const Eigen::Vector3f floor_albedo = g.floor_albedo;
    const __m128 v_ctpm = _mm_set1_ps(ctpm), v_stpm = _mm_set1_ps(stpm);
    const __m128 v_ltpm = _mm_set1_ps(light_tpm), half = _mm_set1_ps(0.5f);
    for (; k + 4 <= count; k += 4) {
      const PixelHit* h[4] = {hits + pixels[k], hits + pixels[k + 1], hits + pixels[k + 2],
                              hits + pixels[k + 3]};
      const __m128 px = _mm_setr_ps(h[0]->p.x(), h[1]->p.x(), h[2]->p.x(), h[3]->p.x());
      const __m128 py = _mm_setr_ps(h[0]->p.y(), h[1]->p.y(), h[2]->p.y(), h[3]->p.y());
      __m128 c;
      if (!g.concrete.sampleNearestLevel4(_mm_mul_ps(px, v_ctpm), _mm_mul_ps(py, v_ctpm),
                                          _mm_mul_ps(_mm_setr_ps(h[0]->footprint, h[1]->footprint,
                                                                 h[2]->footprint, h[3]->footprint),
                                                     v_ctpm),
                                          c)) {
        alignas(16) float lanes[4];
        for (int l = 0; l < 4; ++l)
          lanes[l] = g.concrete.sampleNearestLevel(h[l]->p.x() * ctpm, h[l]->p.y() * ctpm,
                                                   h[l]->footprint * ctpm);
        c = _mm_load_ps(lanes);
      }
      const __m128 shade = floor_shade_grid.at4(_mm_sub_ps(_mm_mul_ps(px, v_stpm), half),
                                                _mm_sub_ps(_mm_mul_ps(py, v_stpm), half));
      const __m128 factor =
          _mm_mul_ps(shade, _mm_add_ps(_mm_set1_ps(0.45f), _mm_mul_ps(_mm_set1_ps(0.95f), c)));
      alignas(16) float lane_factor[4], lane_light[4];
      _mm_store_ps(lane_factor, factor);
      _mm_store_ps(lane_light,
                   floor_light_grid.at4(_mm_mul_ps(px, v_ltpm), _mm_mul_ps(py, v_ltpm)));
      for (int l = 0; l < 4; ++l) {
        albedo[pixels[k + l]] = floor_albedo * lane_factor[l];
        irradiance[pixels[k + l]] = lane_light[l];
      }
    }
  }
#endif
  for (; k < count; ++k) {
    const int x = pixels[k];
    const Eigen::Vector3f& p = hits[x].p;
    albedo[x] = bareFloorAlbedo(p, hits[x].footprint);
    irradiance[x] = floor_light_grid.at(p.x() * light_tpm, p.y() * light_tpm);
  }
}

// The floor's albedo without markings at p (concrete x shade), the concrete sampled at a
// footprint of `footprint_m` metres: shadeFloorBase's scalar path, one point at a time.
Eigen::Vector3f Renderer::Impl::bareFloorAlbedo(const Eigen::Vector3f& p, float footprint_m) const {
  const float ctpm = static_cast<float>(g.concrete_texels_per_metre);
  const float stpm = static_cast<float>(g.shade_texels_per_metre);
  const float c = g.concrete.sampleNearestLevel(p.x() * ctpm, p.y() * ctpm, footprint_m * ctpm);
  const float shade = floor_shade_grid.at(p.x() * stpm - 0.5f, p.y() * stpm - 0.5f);
  return g.floor_albedo * (shade * (0.45f + 0.95f * c));
}

// Painted lines and text decals over the floor albedo of the listed pixels.
void Renderer::Impl::shadeFloorMarkings(const PixelHit* hits, const int* pixels, int count,
                                        Eigen::Vector3f* albedo) const {
  const float ptpm = static_cast<float>(g.paint_texels_per_metre);
  for (int k = 0; k < count; ++k) {
    const int x = pixels[k];
    const Eigen::Vector3f& p = hits[x].p;
    const float fp = hits[x].footprint;
    Eigen::Vector3f a = albedo[x];
    if (paintNear(p.x(), p.y())) {
      float wpaint, ypaint;
      paint.sample(p.x() * ptpm - 0.5f, p.y() * ptpm - 0.5f, fp * ptpm, wpaint, ypaint);
      if (wpaint > 0.002f) a += wpaint * 0.95f * (Eigen::Vector3f(0.86f, 0.86f, 0.84f) - a);
      if (ypaint > 0.002f) a += ypaint * 0.95f * (Eigen::Vector3f(0.88f, 0.7f, 0.1f) - a);
    }
    const size_t cell = cellIndex(p.x(), p.y());
    for (const int* di = decal_grid.begin(cell); di != decal_grid.end(cell); ++di) {
      const Decal& dc = L.floor_decals[*di];
      const float coverage = decalCoverage(dc, p, fp) * dc.opacity;
      if (coverage > 0.0f) a += coverage * (dc.color - a);
    }
    albedo[x] = a;
  }
}

double Renderer::Impl::floorInkContrast(size_t camera, const Eigen::Vector2d& pixel,
                                        int decal) const {
  const Decal& d = L.floor_decals.at(static_cast<size_t>(decal));
  const CameraRays& cr = (*rays).at(camera);
  const int x = std::clamp(static_cast<int>(std::lround(pixel.x())), 0, cr.width - 1);
  const int y = std::clamp(static_cast<int>(std::lround(pixel.y())), 0, cr.height - 1);
  const float vignette = cr.vignette[static_cast<size_t>(y) * cr.width + x];
  const Eigen::Vector3f centre = d.origin + 0.5f * d.size_u * d.axis_u + 0.5f * d.size_v * d.axis_v;
  // The bare floor under the text, the concrete averaged over a glyph's height.
  Eigen::Vector3f floor = bareFloorAlbedo(centre, d.size_v);
  // A number on a painted patch stands out against the patch.
  if (d.backing >= 0) {
    const Decal& patch = L.floor_decals.at(static_cast<size_t>(d.backing));
    floor += patch.opacity * (patch.color - floor);
  }
  // The decal's blend (shadeFloorMarkings) at its mean ink: the opacity times what wear left.
  const Eigen::Vector3f ink = floor + d.opacity * d.ink_kept * (d.color - floor);
  const float scale = floor_light_grid.at(centre.x() * light_tpm, centre.y() * light_tpm) *
                      exposureScale() * vignette;
  // Pass 4's tone curve, then BT.601 luma.
  auto luma = [&](const Eigen::Vector3f& albedo) {
    double value = 0.0;
    const double weight[3] = {0.299, 0.587, 0.114};  // R, G, B
    for (int ch = 0; ch < 3; ++ch) {
      const int idx = std::clamp(static_cast<int>(albedo[ch] * scale), 0, kLutSize - 1);
      value += weight[ch] * gamma_lut[static_cast<size_t>(idx)];
    }
    return value;
  };
  return std::abs(luma(ink) - luma(floor));
}

}  // namespace parkloc::sim
