#pragma once
// A single-channel 8-bit texture with a mip pyramid, for filtered lookups: the level is
// chosen from the footprint of a pixel on the surface, so far text is not aliased and near
// text stays sharp. The lookups are inline: the renderer calls them several times per pixel.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <opencv2/core.hpp>
#include <vector>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace parkloc::sim {

// log2(x) for finite x > 0 within about 1e-5: the exponent bits plus a polynomial in the
// mantissa (std::log2 is a library call; the renderer needs one per texture lookup).
inline float fastLog2(float x) {
  uint32_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const float exponent = static_cast<float>(static_cast<int>((bits >> 23) & 0xff) - 127);
  bits = (bits & 0x007fffffu) | 0x3f800000u;  // mantissa in [1, 2)
  float m;
  std::memcpy(&m, &bits, sizeof m);
  // log2(m) on [1, 2) via s = (m - 1) / (m + 1): log2(m) = 2 / ln 2 (s + s^3/3 + s^5/5 + ...).
  const float s = (m - 1.0f) / (m + 1.0f), s2 = s * s;
  const float series = 1.0f + s2 * (1.0f / 3.0f + s2 * (1.0f / 5.0f + s2 * (1.0f / 7.0f)));
  return exponent + 2.8853900817779268f * s * series;
}

class MipTexture {
 public:
  MipTexture() = default;
  // `wrap`: the texture tiles (floor concrete); otherwise texels outside read as the border.
  explicit MipTexture(const cv::Mat& level0_u8, bool wrap = false);

  bool empty() const { return levels_.empty(); }
  int levelCount() const { return static_cast<int>(levels_.size()); }
  const cv::Mat& levelTexels(int level) const { return levels_.at(level).texels; }
  bool wraps() const { return wrap_; }
  int width() const { return levels_.empty() ? 0 : levels_[0].width; }
  int height() const { return levels_.empty() ? 0 : levels_[0].height; }

  // Value in [0, 1] at level-0 texel coordinates (u, v) (texel centres at integers), for a
  // pixel footprint of `footprint` level-0 texels: trilinear between the two nearest levels.
  float sample(float u, float v, float footprint) const {
    return sampleAtLod(u, v, levelOfDetail(footprint));
  }
  // The continuous level for a footprint, and sample() at it: textures of the same size
  // looked up at the same place share the logarithm.
  static float levelOfDetail(float footprint) {
    return footprint > 1.0f ? fastLog2(footprint) : 0.0f;
  }
  float sampleAtLod(float u, float v, float lod) const {
    const int last = static_cast<int>(levels_.size()) - 1;
    const int l0 = std::min(static_cast<int>(lod), last);
    if (l0 >= last) return bilinear(last, u, v);
    const float t = lod - static_cast<float>(l0);
    const float a = bilinear(l0, u, v);
    if (t < 0.02f) return a;
    return a + t * (bilinear(l0 + 1, u, v) - a);
  }
  // Bilinear at a single level (the nearest one), cheaper for large low-contrast textures.
  float sampleNearestLevel(float u, float v, float footprint) const {
    return bilinear(nearestLevel(footprint), u, v);
  }
#if defined(__SSE2__)
  // sampleNearestLevel() at four points, the same operations lane by lane, when the four
  // pick one level of a tiling power-of-two texture; otherwise false and `out` untouched.
  bool sampleNearestLevel4(__m128 u, __m128 v, __m128 footprint, __m128& out) const {
    if (!wrap_) return false;
    alignas(16) float fp[4];
    _mm_store_ps(fp, footprint);
    const int level = nearestLevel(fp[0]);
    if (nearestLevel(fp[1]) != level || nearestLevel(fp[2]) != level ||
        nearestLevel(fp[3]) != level)
      return false;
    const Level& m = levels_[level];
    if (!m.pow2) return false;
    const __m128 scale = _mm_set1_ps(m.scale), half = _mm_set1_ps(0.5f);
    const __m128 x = _mm_sub_ps(_mm_mul_ps(_mm_add_ps(u, half), scale), half);
    const __m128 y = _mm_sub_ps(_mm_mul_ps(_mm_add_ps(v, half), scale), half);
    const __m128i x0 = floorInt4(x), y0 = floorInt4(y);
    const __m128 ax = _mm_sub_ps(x, _mm_cvtepi32_ps(x0)), ay = _mm_sub_ps(y, _mm_cvtepi32_ps(y0));
    const __m128i one = _mm_set1_epi32(1);
    const __m128i wmask = _mm_set1_epi32(m.width - 1), hmask = _mm_set1_epi32(m.height - 1);
    alignas(16) int ix0[4], ix1[4], iy0[4], iy1[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(ix0), _mm_and_si128(x0, wmask));
    _mm_store_si128(reinterpret_cast<__m128i*>(ix1), _mm_and_si128(_mm_add_epi32(x0, one), wmask));
    _mm_store_si128(reinterpret_cast<__m128i*>(iy0), _mm_and_si128(y0, hmask));
    _mm_store_si128(reinterpret_cast<__m128i*>(iy1), _mm_and_si128(_mm_add_epi32(y0, one), hmask));
    alignas(16) float a[4], b[4], c[4], d[4];
    for (int l = 0; l < 4; ++l) {
      const uint8_t* r0 = m.texels.data + static_cast<size_t>(iy0[l]) * m.width;
      const uint8_t* r1 = m.texels.data + static_cast<size_t>(iy1[l]) * m.width;
      a[l] = r0[ix0[l]];
      b[l] = r0[ix1[l]];
      c[l] = r1[ix0[l]];
      d[l] = r1[ix1[l]];
    }
    const __m128 va = _mm_load_ps(a), vc = _mm_load_ps(c);
    const __m128 top = _mm_add_ps(va, _mm_mul_ps(ax, _mm_sub_ps(_mm_load_ps(b), va)));
    const __m128 bottom = _mm_add_ps(vc, _mm_mul_ps(ax, _mm_sub_ps(_mm_load_ps(d), vc)));
    out = _mm_mul_ps(_mm_add_ps(top, _mm_mul_ps(ay, _mm_sub_ps(bottom, top))),
                     _mm_set1_ps(1.0f / 255.0f));
    return true;
  }
#endif

 private:
  struct Level {
    cv::Mat texels;  // CV_8UC1, continuous
    int width = 0, height = 0;
    float scale = 1.0f;  // level texels per level-0 texel
    bool pow2 = false;   // both sizes powers of two: wrap with masks
  };

  // floor() for finite values in int range, without SSE4.1's roundss.
  static int floorInt(float x) {
    const int i = static_cast<int>(x);
    return i - (static_cast<float>(i) > x ? 1 : 0);
  }
#if defined(__SSE2__)
  static __m128i floorInt4(__m128 x) {
    const __m128i i = _mm_cvttps_epi32(x);
    // The comparison mask is -1 where truncation rounded up.
    return _mm_add_epi32(i, _mm_castps_si128(_mm_cmpgt_ps(_mm_cvtepi32_ps(i), x)));
  }
#endif
  // The level sampleNearestLevel() reads: floor(log2(footprint) + 0.5), the binary exponent
  // of footprint * sqrt(2).
  int nearestLevel(float footprint) const {
    int level = 0;
    if (footprint > 1.0f) {
      const float scaled = footprint * 1.41421356f;
      uint32_t bits;
      std::memcpy(&bits, &scaled, sizeof bits);
      level = static_cast<int>(bits >> 23) - 127;  // positive finite: the sign bit is 0
    }
    return std::min(level, static_cast<int>(levels_.size()) - 1);
  }

  float bilinear(int level, float u, float v) const {
    const Level& m = levels_[level];
    // Level-0 texel centres at integers -> this level's texel centres.
    const float x = (u + 0.5f) * m.scale - 0.5f;
    const float y = (v + 0.5f) * m.scale - 0.5f;
    int x0 = floorInt(x), y0 = floorInt(y);
    const float ax = x - static_cast<float>(x0), ay = y - static_cast<float>(y0);
    int x1, y1;
    const int w = m.width, h = m.height;
    if (wrap_) {
      if (m.pow2) {
        x0 &= w - 1;
        y0 &= h - 1;
      } else {
        x0 = ((x0 % w) + w) % w;
        y0 = ((y0 % h) + h) % h;
      }
      x1 = x0 + 1 == w ? 0 : x0 + 1;
      y1 = y0 + 1 == h ? 0 : y0 + 1;
    } else {
      x1 = std::clamp(x0 + 1, 0, w - 1);
      y1 = std::clamp(y0 + 1, 0, h - 1);
      x0 = std::clamp(x0, 0, w - 1);
      y0 = std::clamp(y0, 0, h - 1);
    }
    const uint8_t* r0 = m.texels.data + static_cast<size_t>(y0) * w;
    const uint8_t* r1 = m.texels.data + static_cast<size_t>(y1) * w;
    const float a = r0[x0], b = r0[x1], c = r1[x0], d = r1[x1];
    const float top = a + ax * (b - a);
    const float bottom = c + ax * (d - c);
    return (top + ay * (bottom - top)) * (1.0f / 255.0f);
  }

  std::vector<Level> levels_;
  bool wrap_ = false;
};

// Two non-wrapping textures of the same size (the white and yellow floor paint) stored
// interleaved, for lookups of both at one place: one address computation and one set of
// cache lines instead of two. Values equal two MipTexture::sample() calls.
class MipTexturePair {
 public:
  MipTexturePair() = default;
  MipTexturePair(const MipTexture& first, const MipTexture& second);

  bool empty() const { return levels_.empty(); }
  // Both values in [0, 1] at level-0 texel coordinates (u, v) for a footprint in texels.
  void sample(float u, float v, float footprint, float& first, float& second) const {
    const float lod = MipTexture::levelOfDetail(footprint);
    const int last = static_cast<int>(levels_.size()) - 1;
    const int l0 = std::min(static_cast<int>(lod), last);
    bilinear(l0, u, v, first, second);
    if (l0 >= last) return;
    const float t = lod - static_cast<float>(l0);
    if (t < 0.02f) return;
    float next_first, next_second;
    bilinear(l0 + 1, u, v, next_first, next_second);
    first += t * (next_first - first);
    second += t * (next_second - second);
  }

 private:
  struct Level {
    cv::Mat texels;  // CV_8UC2, continuous
    int width = 0, height = 0;
    float scale = 1.0f;
  };
  void bilinear(int level, float u, float v, float& first, float& second) const {
    const Level& m = levels_[level];
    const float x = (u + 0.5f) * m.scale - 0.5f;
    const float y = (v + 0.5f) * m.scale - 0.5f;
    const int fx = static_cast<int>(x), fy = static_cast<int>(y);
    int x0 = fx - (static_cast<float>(fx) > x ? 1 : 0),
        y0 = fy - (static_cast<float>(fy) > y ? 1 : 0);
    const float ax = x - static_cast<float>(x0), ay = y - static_cast<float>(y0);
    const int w = m.width, h = m.height;
    const int x1 = std::clamp(x0 + 1, 0, w - 1), y1 = std::clamp(y0 + 1, 0, h - 1);
    x0 = std::clamp(x0, 0, w - 1);
    y0 = std::clamp(y0, 0, h - 1);
    const uint8_t* r0 = m.texels.data + 2 * static_cast<size_t>(y0) * w;
    const uint8_t* r1 = m.texels.data + 2 * static_cast<size_t>(y1) * w;
    for (int c = 0; c < 2; ++c) {
      const float a = r0[2 * x0 + c], b = r0[2 * x1 + c], cc = r1[2 * x0 + c], d = r1[2 * x1 + c];
      const float top = a + ax * (b - a);
      const float bottom = cc + ax * (d - cc);
      (c == 0 ? first : second) = (top + ay * (bottom - top)) * (1.0f / 255.0f);
    }
  }
  std::vector<Level> levels_;
};

}  // namespace parkloc::sim
