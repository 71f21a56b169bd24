#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "sim/legibility.h"
#include "sim/renderer_impl.h"

namespace parkloc::sim {

// The tone curve: scene brightness (irradiance x albedo x exposure, up to kLutMax) to 8-bit
// values.
void Renderer::Impl::buildToneCurve() {
  gamma_lut.resize(kLutSize);
  for (int i = 0; i < kLutSize; ++i) {
    const float x = kLutMax * i / (kLutSize - 1);
    // Soft shoulder so lamps clip gently, then sRGB-like gamma.
    const float y = x < 0.8f ? x : 0.8f + 0.2f * std::tanh((x - 0.8f) / 0.2f);
    gamma_lut[i] =
        cv::saturate_cast<uint8_t>(255.0f * std::pow(std::clamp(y, 0.0f, 1.0f), 1.0f / 2.2f));
  }
}

// Pass 4 over pixels [begin, end) of a row: exposure, vignetting, tone curve and sensor
// noise (three values per pixel, drawn while tracing).
void Renderer::Impl::exposePixels(const PixelHit* hits, const Eigen::Vector3f* albedo,
                                  const float* irradiance, const float* vignette,
                                  const float* noise, int begin, int end, uint8_t* out) const {
  const float exposure_scale = exposureScale();
  const float* lut = gamma_lut.data();
  const float sigma = light.noise_sigma;
#if defined(__SSE2__)
  const __m128 v_sigma = _mm_set1_ps(sigma);
  const __m128 v_lut_max = _mm_set1_ps(static_cast<float>(kLutSize - 1));
#endif
  for (int x = begin; x < end; ++x) {
    if (hits[x].surface == Surface::kNone) {
      out[3 * x] = out[3 * x + 1] = out[3 * x + 2] = 0;
      continue;
    }
    const float scale = irradiance[x] * exposure_scale * vignette[x];
    const float* n3 = noise + 3 * x;
#if defined(__SSE2__)
    // The three channels at once, the scalar loop's operations lane by lane: the
    // index clamp is done before truncating (the same for any value below 2^31),
    // packing saturates as the clamp to [0, 255] does.
    const __m128 rgb = _mm_loadu_ps(albedo[x].data());
    const __m128 bgr = _mm_shuffle_ps(rgb, rgb, _MM_SHUFFLE(3, 0, 1, 2));
    const __m128 index =
        _mm_min_ps(_mm_max_ps(_mm_mul_ps(bgr, _mm_set1_ps(scale)), _mm_setzero_ps()), v_lut_max);
    alignas(16) int idx[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(idx), _mm_cvttps_epi32(index));
    const __m128 tone = _mm_setr_ps(lut[idx[0]], lut[idx[1]], lut[idx[2]], 0.0f);
    const __m128i v = _mm_cvtps_epi32(_mm_add_ps(tone, _mm_mul_ps(v_sigma, _mm_loadu_ps(n3))));
    const uint32_t bytes = static_cast<uint32_t>(
        _mm_cvtsi128_si32(_mm_packus_epi16(_mm_packs_epi32(v, v), _mm_setzero_si128())));
    out[3 * x] = static_cast<uint8_t>(bytes);
    out[3 * x + 1] = static_cast<uint8_t>(bytes >> 8);
    out[3 * x + 2] = static_cast<uint8_t>(bytes >> 16);
#else
    for (int ch = 0; ch < 3; ++ch) {
      // BGR output.
      const int idx = std::min(kLutSize - 1, static_cast<int>(albedo[x][2 - ch] * scale));
      // saturate_cast without its branches (lamps clip, noise straddles the limits).
      const int v = cvRound(lut[std::max(0, idx)] + sigma * n3[ch]);
      out[3 * x + ch] = static_cast<uint8_t>(std::min(255, std::max(0, v)));
    }
#endif
  }
}

// Defocus and motion blur: the same blur the labels' legibility rule assumes
// (sim/legibility.h).
void Renderer::Impl::applyLensBlur(cv::Mat& img, const geometry::RigCamera& cam) const {
  const ImageBlur blur = imageBlur(light, cam);
  if (blur.defocus_sigma_px > 0.0)
    cv::GaussianBlur(img, img, cv::Size(0, 0), blur.defocus_sigma_px);
  if (blur.motion_length_px > 1.0)
    cv::blur(img, img, cv::Size(static_cast<int>(blur.motion_length_px), 1));
}

}  // namespace parkloc::sim
