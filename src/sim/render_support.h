#pragma once
// The renderer's building blocks shared by its passes (sim/renderer_impl.h): bilinear lookups
// in a float map, flat per-cell index lists, SSE lane selects and the sensor-noise generator.
// Internal to the sim module.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <opencv2/core.hpp>
#include <vector>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace parkloc::sim::detail {

// Boxes are culled per square tile of this many pixels: four neighbouring pixels of a row
// share a tile, so the SSE tracing pass tests one box list for all four.
constexpr int kTile = 16;
constexpr int kChunk = 256;  // pixels; a multiple of kTile
constexpr float kInf = std::numeric_limits<float>::infinity();

// A CV_32F map viewed for bilinear lookups, with what every lookup needs at hand (cv::Mat
// keeps its row step one indirection away). The map must outlive the view.
struct FloatGrid {
  const float* data = nullptr;
  int cols = 0, rows = 0;
  size_t stride = 0;  // floats per row
  float xmax = 0.0f, ymax = 0.0f;
  FloatGrid() = default;
  explicit FloatGrid(const cv::Mat& m)
      : data(m.ptr<float>()),
        cols(m.cols),
        rows(m.rows),
        stride(m.step1()),
        xmax(static_cast<float>(m.cols - 1) - 1e-3f),
        ymax(static_cast<float>(m.rows - 1) - 1e-3f) {
    CV_Assert(m.type() == CV_32FC1 && !m.empty());
  }
  // Bilinear at (x, y) in texels (centres at integers); outside (or NaN) reads the border.
  float at(float x, float y) const {
    x = x >= 0.0f ? std::min(x, xmax) : 0.0f;  // NaN compares false: reads texel 0
    y = y >= 0.0f ? std::min(y, ymax) : 0.0f;
    const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
    const float ax = x - static_cast<float>(x0), ay = y - static_cast<float>(y0);
    const float* r0 = data + stride * static_cast<size_t>(y0);
    const float* r1 = y0 + 1 < rows ? r0 + stride : r0;
    const int x1 = x0 + 1 < cols ? x0 + 1 : x0;
    const float top = r0[x0] + ax * (r0[x1] - r0[x0]);
    const float bottom = r1[x0] + ax * (r1[x1] - r1[x0]);
    return top + ay * (bottom - top);
  }
#if defined(__SSE2__)
  // at() for four points, the same operations lane by lane (std::min(a, b) is
  // _mm_min_ps(b, a)); needs vectorizable() to hold.
  bool vectorizable() const { return cols >= 2 && rows >= 2 && cols <= 8192 && rows <= 8192; }
  __m128 at4(__m128 x, __m128 y) const {
    const __m128 zero = _mm_setzero_ps();
    x = _mm_and_ps(_mm_cmpge_ps(x, zero), _mm_min_ps(_mm_set1_ps(xmax), x));
    y = _mm_and_ps(_mm_cmpge_ps(y, zero), _mm_min_ps(_mm_set1_ps(ymax), y));
    const __m128i x0 = _mm_cvttps_epi32(x), y0 = _mm_cvttps_epi32(y);
    const __m128 ax = _mm_sub_ps(x, _mm_cvtepi32_ps(x0)), ay = _mm_sub_ps(y, _mm_cvtepi32_ps(y0));
    alignas(16) int ix[4], iy[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(ix), x0);
    _mm_store_si128(reinterpret_cast<__m128i*>(iy), y0);
    // Inside the clamped range x0 + 1 < cols and y0 + 1 < rows (sizes below 8192).
    alignas(16) float a[4], b[4], c[4], d[4];
    for (int l = 0; l < 4; ++l) {
      const float* r0 = data + stride * static_cast<size_t>(iy[l]) + ix[l];
      a[l] = r0[0];
      b[l] = r0[1];
      c[l] = r0[stride];
      d[l] = r0[stride + 1];
    }
    const __m128 va = _mm_load_ps(a), vc = _mm_load_ps(c);
    const __m128 top = _mm_add_ps(va, _mm_mul_ps(ax, _mm_sub_ps(_mm_load_ps(b), va)));
    const __m128 bottom = _mm_add_ps(vc, _mm_mul_ps(ax, _mm_sub_ps(_mm_load_ps(d), vc)));
    return _mm_add_ps(top, _mm_mul_ps(ay, _mm_sub_ps(bottom, top)));
  }
#endif
};

// Index lists per cell of a grid, stored flat: the items of cell c are
// items[start[c], start[c + 1]).
struct CellLists {
  std::vector<int> start, items;
  void build(const std::vector<std::vector<int>>& per_cell) {
    start.assign(per_cell.size() + 1, 0);
    for (size_t c = 0; c < per_cell.size(); ++c)
      start[c + 1] = start[c] + static_cast<int>(per_cell[c].size());
    items.clear();
    items.reserve(static_cast<size_t>(start.back()));
    for (const auto& cell : per_cell) items.insert(items.end(), cell.begin(), cell.end());
  }
  const int* begin(size_t c) const { return items.data() + start[c]; }
  const int* end(size_t c) const { return items.data() + start[c + 1]; }
};

#if defined(__SSE2__)
// Lane-wise mask ? a : b.
inline __m128 laneSelect(__m128 mask, __m128 a, __m128 b) {
  return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b));
}
inline __m128i laneSelectInt(__m128 mask, __m128i a, __m128i b) {
  const __m128i m = _mm_castps_si128(mask);
  return _mm_or_si128(_mm_and_si128(m, a), _mm_andnot_si128(m, b));
}
#endif

// Small fast generator for sensor noise, seeded per row so rows can run in any order.
struct XorShift {
  uint64_t s;
  explicit XorShift(uint64_t seed) : s(seed * 0x9E3779B97F4A7C15ULL + 0x632BE59BD9B4E019ULL) {
    if (s == 0) s = 1;
  }
  uint32_t next() {
    s ^= s << 13;
    s ^= s >> 7;
    s ^= s << 17;
    return static_cast<uint32_t>(s >> 32);
  }
  // Three approximately standard normal values (sums of two uniforms, unit variance).
  void gauss3(float out[3]) {
    const uint32_t a = next(), b = next(), c = next();
    const float k = 2.4494897f / 65536.0f;
    // The sums are exact in int as in float (below 2^17): one conversion each.
    out[0] = static_cast<float>(static_cast<int>((a & 0xffff) + (a >> 16)) - 65535) * k;
    out[1] = static_cast<float>(static_cast<int>((b & 0xffff) + (b >> 16)) - 65535) * k;
    out[2] = static_cast<float>(static_cast<int>((c & 0xffff) + (c >> 16)) - 65535) * k;
  }
};

}  // namespace parkloc::sim::detail
