#include "sim/renderer.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <random>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "sim/legibility.h"

namespace parkloc::sim {
namespace {

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

// Fisheye projection without the field-of-view limit, for culling: points past the model's
// last angle land beyond the image border instead of failing, so a box that is partly behind
// the camera still gets a tight bound. Empty only near the axis pointing backwards.
std::optional<Eigen::Vector2d> projectForCulling(const geometry::CameraModel& m,
                                                 const Eigen::Vector3d& p) {
  if (m.type != geometry::CameraModelType::kFisheye) return m.project(p);
  const double r = p.head<2>().norm();
  if (r < 1e-12)
    return p.z() > 0 ? std::optional<Eigen::Vector2d>(Eigen::Vector2d(m.cx, m.cy)) : std::nullopt;
  const double theta = std::atan2(r, p.z());
  if (theta > 2.9) return std::nullopt;
  const double t = std::min(theta, m.max_theta);
  const double t2 = t * t;
  const auto& k = m.distortion;
  // Past max_theta continue linearly with the slope there (the model is monotonic up to it).
  const double td =
      t * (1 + t2 * (k[0] + t2 * (k[1] + t2 * (k[2] + t2 * k[3])))) + (theta - t) * 1.2;
  return Eigen::Vector2d(m.fx * p.x() / r * td + m.cx, m.fy * p.y() / r * td + m.cy);
}

}  // namespace

CameraRays buildCameraRays(const geometry::CameraModel& model, float vignetting) {
  CameraRays r;
  r.width = model.width;
  r.height = model.height;
  const size_t n = static_cast<size_t>(r.width) * r.height;
  r.rays.assign(n, Eigen::Vector3f::Zero());
  r.pixel_angle.assign(n, 0.0f);
  r.vignette.assign(n, 0.0f);
  cv::parallel_for_(cv::Range(0, r.height), [&](const cv::Range& range) {
    for (int y = range.start; y < range.end; ++y)
      for (int x = 0; x < r.width; ++x) {
        const auto ray = model.unproject(Eigen::Vector2d(x, y));
        if (ray) r.rays[static_cast<size_t>(y) * r.width + x] = ray->cast<float>();
      }
  });
  const double rmax = std::hypot(r.width / 2.0, r.height / 2.0);
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const size_t i = static_cast<size_t>(y) * r.width + x;
      const Eigen::Vector3f& a = r.rays[i];
      if (a.isZero()) continue;
      const Eigen::Vector3f& b = r.rays[x + 1 < r.width ? i + 1 : i - 1];
      const Eigen::Vector3f& c = r.rays[y + 1 < r.height ? i + r.width : i - r.width];
      const float da = b.isZero() ? 0.0f : std::acos(std::clamp(a.dot(b), -1.0f, 1.0f));
      const float db = c.isZero() ? 0.0f : std::acos(std::clamp(a.dot(c), -1.0f, 1.0f));
      r.pixel_angle[i] =
          std::max(1e-4f, std::sqrt(da * db) > 0.0f ? std::sqrt(da * db) : std::max(da, db));
      const double rr = std::hypot(x - model.cx, y - model.cy) / rmax;
      r.vignette[i] = static_cast<float>(1.0 - vignetting * rr * rr);
    }
  return r;
}

std::vector<CameraRays> buildRigRays(const geometry::Rig& rig) {
  std::vector<CameraRays> out;
  for (const auto& c : rig.cameras) out.push_back(buildCameraRays(c.model));
  return out;
}

LightingOptions lightingForCondition(const std::string& condition, uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto u = [&](double a, double b) {
    return static_cast<float>(std::uniform_real_distribution<double>(a, b)(rng));
  };
  LightingOptions l;
  l.lamp_seed = seed ^ 0x5bd1e995ULL;
  if (condition == "weak") {
    l.ambient = u(0.02f, 0.05f);
    l.lamp_power = u(2.0f, 3.5f);
    l.lamps_on_share = u(0.4f, 0.7f);
    l.exposure = u(0.65f, 0.95f);
    l.noise_sigma = u(4.0f, 7.0f);
  } else {
    l.ambient = u(0.15f, 0.3f);
    l.lamp_power = u(5.0f, 8.0f);
    l.lamps_on_share = u(0.9f, 1.0f);
    l.exposure = u(0.85f, 1.1f);
    l.noise_sigma = u(1.0f, 2.0f);
    if (condition == "blur") {
      l.defocus_sigma = u(1.0f, 2.0f);
      l.motion_blur_px = u(4.0f, 9.0f);
    }
  }
  return l;
}

struct Renderer::Impl {
  const Garage& g;
  const GarageLevel& L;
  geometry::Rig rig;
  std::shared_ptr<const std::vector<CameraRays>> rays;
  LightingOptions light;
  std::vector<Lamp> lamps_on;
  std::vector<uint8_t> lamp_is_on;  // per lamp of the level
  // Irradiance on vertical surfaces facing +x, -x, +y, -y at 1 m height (4 texels per metre).
  cv::Mat vertical_light[4];
  FloatGrid vertical_grid[4];
  static constexpr float kVerticalTpm = 4.0f;
  // Cells (0.5 m) with any white / yellow paint nearby: floor pixels elsewhere skip the lookup.
  std::vector<uint8_t> paint_mask;
  MipTexturePair paint;  // white and yellow
  std::vector<Eigen::Vector3f> box_decal_normals;
  int paint_mask_w = 0, paint_mask_h = 0;
  // Floor irradiance (10 texels per metre) and ceiling brightness.
  cv::Mat floor_light, ceiling_light;
  FloatGrid floor_light_grid, ceiling_light_grid, floor_shade_grid;
  float light_tpm = 10.0f;
  // Uniform grids (1 m cells) of floor decals and of lamps.
  int grid_w = 0, grid_h = 0;
  CellLists decal_grid, lamp_grid;
  // Per camera: its unit rays turned into the vehicle frame, with the pixel angle in w (0
  // where the model has no ray). The vehicle only turns about z, so per frame a pixel's map
  // ray is this one rotated by the yaw: two multiply-adds instead of a 3x3 product.
  struct VehicleRay {
    float x, y, z, angle;
  };
  std::vector<std::vector<VehicleRay>> vehicle_rays;
  // Per camera: 1 where the pixel's ray meets the recording car's body (empty: no body).
  std::vector<std::vector<uint8_t>> ego_masks;
  std::vector<float> gamma_lut;  // 8-bit values, as float for the noise sum
  static constexpr int kLutSize = 4096;
  static constexpr float kLutMax = 1.5f;

  Impl(const Garage& garage, int level, const geometry::Rig& r,
       std::shared_ptr<const std::vector<CameraRays>> ry, const LightingOptions& li)
      : g(garage), L(garage.levels.at(level)), rig(r), rays(std::move(ry)), light(li) {
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
      addToGrid(lamps_per_cell, l.center - l.half_size, l.center + l.half_size,
                static_cast<int>(i));
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
    gamma_lut.resize(kLutSize);
    for (int i = 0; i < kLutSize; ++i) {
      const float x = kLutMax * i / (kLutSize - 1);
      // Soft shoulder so lamps clip gently, then sRGB-like gamma.
      const float y = x < 0.8f ? x : 0.8f + 0.2f * std::tanh((x - 0.8f) / 0.2f);
      gamma_lut[i] =
          cv::saturate_cast<uint8_t>(255.0f * std::pow(std::clamp(y, 0.0f, 1.0f), 1.0f / 2.2f));
    }
  }

  void addToGrid(std::vector<std::vector<int>>& grid, const Eigen::Vector2f& lo,
                 const Eigen::Vector2f& hi, int index) const {
    const int x0 = std::clamp(static_cast<int>(std::floor(lo.x())), 0, grid_w - 1);
    const int x1 = std::clamp(static_cast<int>(std::floor(hi.x())), 0, grid_w - 1);
    const int y0 = std::clamp(static_cast<int>(std::floor(lo.y())), 0, grid_h - 1);
    const int y1 = std::clamp(static_cast<int>(std::floor(hi.y())), 0, grid_h - 1);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) grid[static_cast<size_t>(y) * grid_w + x].push_back(index);
  }

  size_t cellIndex(float x, float y) const {
    const int ix = std::clamp(static_cast<int>(x), 0, grid_w - 1);
    const int iy = std::clamp(static_cast<int>(y), 0, grid_h - 1);
    return static_cast<size_t>(iy) * grid_w + ix;
  }

  // Coverage of decal d at point p (0 outside); footprint in metres.
  float decalCoverage(const Decal& d, const Eigen::Vector3f& p, float footprint_m) const {
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

  // Irradiance on a vertical surface with horizontal normal n at p, from the lit lamps nearby
  // and light bounced from the floor.
  float verticalLightExact(const Eigen::Vector3f& p, const Eigen::Vector2f& n) const {
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
  float verticalLight(const Eigen::Vector3f& p, const Eigen::Vector3f& n) const {
    const int k = n.x() > 0.5f ? 0 : n.x() < -0.5f ? 1 : n.y() > 0.5f ? 2 : 3;
    const float h = std::clamp(p.z() / static_cast<float>(g.ceiling_height), 0.0f, 1.0f);
    return vertical_grid[k].at(p.x() * kVerticalTpm, p.y() * kVerticalTpm) * (0.8f + 0.5f * h * h);
  }
  // A parked car's lower box (cars stand along y): wheels on the sides, a dark sill and
  // underbody, lamps at the ends.
  static Eigen::Vector3f carBodyAlbedo(const Box& b, const Eigen::Vector3f& p,
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
  bool paintNear(float x, float y) const {
    const int mx = std::clamp(static_cast<int>(x * 2.0f), 0, paint_mask_w - 1);
    const int my = std::clamp(static_cast<int>(y * 2.0f), 0, paint_mask_h - 1);
    return paint_mask[static_cast<size_t>(my) * paint_mask_w + mx] != 0;
  }

  // Boxes that may cover each 16x16 tile of camera ci's image, as flat lists per tile.
  CellLists cullBoxes(size_t ci, const geometry::Rigid3& map_from_camera) const {
    const geometry::RigCamera& cam = rig.cameras[ci];
    const CameraRays& cr = (*rays)[ci];
    const Eigen::Vector3f o = map_from_camera.translation().cast<float>();
    const geometry::Rigid3 camera_from_map = map_from_camera.inverse();
    const int W = cr.width, Hh = cr.height;
    const int tiles_x = (W + kTile - 1) / kTile, tiles_y = (Hh + kTile - 1) / kTile;
    // Box culling: the tiles each box may cover, from projected points on its edges.
    std::vector<std::vector<int>> tiles(static_cast<size_t>(tiles_x) * tiles_y);
    for (size_t bi = 0; bi < L.boxes.size(); ++bi) {
      const Box& b = L.boxes[bi];
      const Eigen::Vector3f centre = 0.5f * (b.lo + b.hi);
      if ((centre - o).head<2>().norm() > 60.0f) continue;
      const Eigen::Vector3f near_pt = o.cwiseMax(b.lo).cwiseMin(b.hi);
      bool full = (near_pt - o).norm() < 0.3f;
      int failed = 0, ok = 0;
      float x0 = kInf, y0 = kInf, x1 = -kInf, y1 = -kInf;
      constexpr int kSteps = 6;
      for (int e = 0; e < 12 && !full; ++e) {
        // Edge e: along axis a = e / 4, the other two coordinates from the bits of e % 4.
        const int a = e / 4, bits = e % 4;
        const int a1 = (a + 1) % 3, a2 = (a + 2) % 3;
        for (int s = 0; s <= kSteps; ++s) {
          Eigen::Vector3d p;
          p[a] = b.lo[a] + (b.hi[a] - b.lo[a]) * s / double(kSteps);
          p[a1] = (bits & 1) ? b.hi[a1] : b.lo[a1];
          p[a2] = (bits & 2) ? b.hi[a2] : b.lo[a2];
          const auto px = projectForCulling(cam.model, camera_from_map * p);
          if (!px) {
            ++failed;
            continue;
          }
          ++ok;
          x0 = std::min(x0, float(px->x()));
          y0 = std::min(y0, float(px->y()));
          x1 = std::max(x1, float(px->x()));
          y1 = std::max(y1, float(px->y()));
        }
      }
      if (!full && ok == 0) continue;
      if (failed > 0) full = true;
      if (!full && (x1 < -0.5f || y1 < -0.5f || x0 > W || y0 > Hh)) continue;
      int tx0 = 0, ty0 = 0, tx1 = tiles_x - 1, ty1 = tiles_y - 1;
      if (!full) {
        const float margin = 4.0f + 0.08f * std::max(x1 - x0, y1 - y0);
        tx0 = std::max(0, static_cast<int>(std::floor((x0 - margin) / kTile)));
        ty0 = std::max(0, static_cast<int>(std::floor((y0 - margin) / kTile)));
        tx1 = std::min(tiles_x - 1, static_cast<int>(std::floor((x1 + margin) / kTile)));
        ty1 = std::min(tiles_y - 1, static_cast<int>(std::floor((y1 + margin) / kTile)));
      }
      for (int ty = ty0; ty <= ty1; ++ty)
        for (int tx = tx0; tx <= tx1; ++tx)
          tiles[static_cast<size_t>(ty) * tiles_x + tx].push_back(static_cast<int>(bi));
    }
    CellLists lists;
    lists.build(tiles);
    return lists;
  }

  // Shading of a box face hit at p (ray d, axis of the face hit_axis).
  Eigen::Vector3f boxAlbedo(const Box& b, const Eigen::Vector3f& p, const Eigen::Vector3f& d,
                            const Eigen::Vector3f& n, float footprint) const {
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

  // What the ray of one pixel hit: the output of the tracing pass over a chunk of a row, the
  // input of its shading passes. Grouping the work by kind keeps each loop short and lets
  // the floor lookups (most pixels) run four at a time.
  enum class Surface : uint8_t { kNone, kFloor, kCeiling, kWall, kBox, kEgo };
  struct PixelHit {
    Eigen::Vector3f p, d;
    float footprint;  // metres; on the floor already divided by the slant
    int box;
    Surface surface;
    uint8_t axis;  // the axis of the face's normal (walls and boxes)
  };
  struct RowBuffers {
    std::vector<PixelHit> hits;
    std::vector<int> floor_pixels;
    std::vector<Eigen::Vector3f> albedo;
    std::vector<float> irradiance;
    std::vector<float> noise;  // three values per pixel
    // albedo and noise have one float to spare: the last pixel's values load as four.
    explicit RowBuffers(int width)
        : hits(static_cast<size_t>(width)),
          floor_pixels(static_cast<size_t>(width)),
          albedo(static_cast<size_t>(width) + 1, Eigen::Vector3f::Zero()),
          irradiance(static_cast<size_t>(width)),
          noise(3 * static_cast<size_t>(width) + 1) {}
  };

  cv::Mat renderCamera(size_t ci, const geometry::Pose2& pose, uint64_t seed) const {
    const geometry::RigCamera& cam = rig.cameras.at(ci);
    const CameraRays& cr = (*rays).at(ci);
    const std::vector<VehicleRay>& vrays = vehicle_rays.at(ci);
    const std::vector<uint8_t>& ego_mask = ego_masks.at(ci);
    const geometry::Rigid3 map_from_camera = pose.toRigid3() * cam.vehicle_from_camera;
    const Eigen::Vector3f o = map_from_camera.translation().cast<float>();
    const float cos_yaw = static_cast<float>(std::cos(pose.yaw));
    const float sin_yaw = static_cast<float>(std::sin(pose.yaw));
    const int W = cr.width, Hh = cr.height;
    const int tiles_x = (W + kTile - 1) / kTile;
    const CellLists tiles = cullBoxes(ci, map_from_camera);
    // Box corners relative to the camera centre, for the slab tests.
    struct RelativeBox {
      float lo[3], hi[3];
    };
    std::vector<RelativeBox> rel(L.boxes.size());
    for (size_t bi = 0; bi < L.boxes.size(); ++bi)
      for (int a = 0; a < 3; ++a) {
        rel[bi].lo[a] = L.boxes[bi].lo[a] - o[a];
        rel[bi].hi[a] = L.boxes[bi].hi[a] - o[a];
      }

    cv::Mat img(Hh, W, CV_8UC3);
    // Signed distances from the camera centre to the walls, floor and ceiling per axis.
    const float wall_x[2] = {0.0f - o.x(), static_cast<float>(g.size.x()) - o.x()};
    const float wall_y[2] = {0.0f - o.y(), static_cast<float>(g.size.y()) - o.y()};
    const float wall_z[2] = {0.0f - o.z(), static_cast<float>(g.ceiling_height) - o.z()};
    const float exposure_scale = exposureScale();
#if defined(__SSE2__)
    const __m128 v_cos = _mm_set1_ps(cos_yaw), v_sin = _mm_set1_ps(sin_yaw);
    const __m128 v_wall_x0 = _mm_set1_ps(wall_x[0]), v_wall_x1 = _mm_set1_ps(wall_x[1]);
    const __m128 v_wall_y0 = _mm_set1_ps(wall_y[0]), v_wall_y1 = _mm_set1_ps(wall_y[1]);
    const __m128 v_wall_z0 = _mm_set1_ps(wall_z[0]), v_wall_z1 = _mm_set1_ps(wall_z[1]);
#endif

    // Stripes of 8 rows: few enough to reuse the row buffers, enough to balance the threads.
    const int stripes = std::max(1, Hh / 8);
    cv::parallel_for_(
        cv::Range(0, Hh),
        [&](const cv::Range& range) {
          RowBuffers buf(W);
          const RelativeBox* boxes = rel.data();
          const float* lut = gamma_lut.data();
          const float sigma = light.noise_sigma;
#if defined(__SSE2__)
          const __m128 v_sigma = _mm_set1_ps(sigma);
          const __m128 v_lut_max = _mm_set1_ps(static_cast<float>(kLutSize - 1));
#endif
          for (int y = range.start; y < range.end; ++y) {
            const VehicleRay* row_rays = vrays.data() + static_cast<size_t>(y) * W;
            const uint8_t* row_ego =
                ego_mask.empty() ? nullptr : ego_mask.data() + static_cast<size_t>(y) * W;
            const size_t tile_row = static_cast<size_t>(y / kTile) * tiles_x;
            PixelHit* hits = buf.hits.data();
            // Sensor noise, drawn in pixel order from a generator seeded per row so rows can
            // run in any order. Drawn while tracing: the generator's serial chain then overlaps
            // with the tracing arithmetic.
            XorShift noise(seed ^ (static_cast<uint64_t>(ci) << 40) ^
                           (static_cast<uint64_t>(y) << 20));
            float* row_noise = buf.noise.data();
            uint8_t* out = img.ptr<uint8_t>(y);
            const float* row_vignette = cr.vignette.data() + static_cast<size_t>(y) * W;
            // The passes run over chunks of the row small enough for their buffers to stay
            // in the L1 cache; chunks go left to right, so the noise keeps its order.
            for (int chunk = 0; chunk < W; chunk += kChunk) {
              const int chunk_end = std::min(W, chunk + kChunk);
              int floor_count = 0;
              // Pass 1: trace every pixel's ray. record() keeps what a ray hit and draws its
              // noise, in pixel order.
              const auto record = [&](int x, const Eigen::Vector3f& d, float t, int surface,
                                      int hit_box, int hit_axis, float angle) {
                PixelHit& h = hits[x];
                if (row_ego && row_ego[x]) {  // the car's own body, in front of everything
                  noise.gauss3(row_noise + 3 * x);
                  h.p = o;
                  h.d = d;
                  h.surface = Surface::kEgo;
                  return;
                }
                if (!(t > 0.0f && t < 1e4f)) return;  // camera outside the level: black
                noise.gauss3(row_noise + 3 * x);
                h.p = o + t * d;
                h.d = d;
                h.footprint = t * angle;
                h.box = hit_box;
                if (hit_box >= 0) {
                  h.surface = Surface::kBox;
                  h.axis = static_cast<uint8_t>(hit_axis);
                } else if (surface == 2 && d.z() < 0) {
                  h.surface = Surface::kFloor;
                  h.footprint /= std::sqrt(std::max(0.02f, -d.z()));  // slant
                  buf.floor_pixels[static_cast<size_t>(floor_count++)] = x;
                } else if (surface == 2) {
                  h.surface = Surface::kCeiling;
                } else {
                  h.surface = Surface::kWall;
                  h.axis = static_cast<uint8_t>(surface);
                }
              };
              int x = chunk;
#if defined(__SSE2__)
              // Four pixels at a time; they share a 16x16 tile, so one list of boxes. Every
              // operation is the scalar loop's below, lane by lane (std::min(a, b) is
              // _mm_min_ps(b, a)), so both give the same bits.
              for (; x + 4 <= chunk_end; x += 4) {
                __m128 rx = _mm_loadu_ps(&row_rays[x].x), ry = _mm_loadu_ps(&row_rays[x + 1].x);
                __m128 rz = _mm_loadu_ps(&row_rays[x + 2].x), ra = _mm_loadu_ps(&row_rays[x + 3].x);
                _MM_TRANSPOSE4_PS(rx, ry, rz, ra);
                const __m128 dx = _mm_sub_ps(_mm_mul_ps(v_cos, rx), _mm_mul_ps(v_sin, ry));
                const __m128 dy = _mm_add_ps(_mm_mul_ps(v_sin, rx), _mm_mul_ps(v_cos, ry));
                const __m128 dz = rz;
                const __m128 one = _mm_set1_ps(1.0f), zero = _mm_setzero_ps();
                const __m128 ix = _mm_div_ps(one, dx), iy = _mm_div_ps(one, dy),
                             iz = _mm_div_ps(one, dz);
                const __m128 tx =
                    _mm_mul_ps(laneSelect(_mm_cmpgt_ps(dx, zero), v_wall_x1, v_wall_x0), ix);
                const __m128 ty =
                    _mm_mul_ps(laneSelect(_mm_cmpgt_ps(dy, zero), v_wall_y1, v_wall_y0), iy);
                const __m128 tz =
                    _mm_mul_ps(laneSelect(_mm_cmpgt_ps(dz, zero), v_wall_z1, v_wall_z0), iz);
                __m128 t = tx;
                __m128i surface = _mm_setzero_si128();
                __m128 closer = _mm_cmplt_ps(ty, t);
                t = laneSelect(closer, ty, t);
                surface = laneSelectInt(closer, _mm_set1_epi32(1), surface);
                closer = _mm_cmplt_ps(tz, t);
                t = laneSelect(closer, tz, t);
                surface = laneSelectInt(closer, _mm_set1_epi32(2), surface);
                __m128i hit_box = _mm_set1_epi32(-1), hit_axis = _mm_setzero_si128();
                const size_t tile = tile_row + static_cast<size_t>(x / kTile);
                for (const int* bi = tiles.begin(tile); bi != tiles.end(tile); ++bi) {
                  const RelativeBox& b = boxes[*bi];
                  const __m128 ax0 = _mm_mul_ps(_mm_set1_ps(b.lo[0]), ix);
                  const __m128 ax1 = _mm_mul_ps(_mm_set1_ps(b.hi[0]), ix);
                  const __m128 ay0 = _mm_mul_ps(_mm_set1_ps(b.lo[1]), iy);
                  const __m128 ay1 = _mm_mul_ps(_mm_set1_ps(b.hi[1]), iy);
                  const __m128 az0 = _mm_mul_ps(_mm_set1_ps(b.lo[2]), iz);
                  const __m128 az1 = _mm_mul_ps(_mm_set1_ps(b.hi[2]), iz);
                  const __m128 nx = _mm_min_ps(ax1, ax0), ny = _mm_min_ps(ay1, ay0),
                               nz = _mm_min_ps(az1, az0);
                  const __m128 tnear = _mm_max_ps(_mm_max_ps(nz, ny), nx);
                  const __m128 tfar = _mm_min_ps(
                      _mm_min_ps(_mm_max_ps(az1, az0), _mm_max_ps(ay1, ay0)), _mm_max_ps(ax1, ax0));
                  const __m128 hit = _mm_and_ps(_mm_and_ps(_mm_cmple_ps(tnear, tfar),
                                                           _mm_cmpgt_ps(tnear, _mm_set1_ps(1e-4f))),
                                                _mm_cmplt_ps(tnear, t));
                  if (_mm_movemask_ps(hit) == 0) continue;
                  t = laneSelect(hit, tnear, t);
                  hit_box = laneSelectInt(hit, _mm_set1_epi32(*bi), hit_box);
                  const __m128i axis = laneSelectInt(
                      _mm_cmpeq_ps(tnear, nx), _mm_setzero_si128(),
                      laneSelectInt(_mm_cmpeq_ps(tnear, ny), _mm_set1_epi32(1), _mm_set1_epi32(2)));
                  hit_axis = laneSelectInt(hit, axis, hit_axis);
                }
                alignas(16) float lane_t[4], lane_dx[4], lane_dy[4], lane_dz[4], lane_angle[4];
                alignas(16) int lane_surface[4], lane_box[4], lane_axis[4];
                _mm_store_ps(lane_t, t);
                _mm_store_ps(lane_dx, dx);
                _mm_store_ps(lane_dy, dy);
                _mm_store_ps(lane_dz, dz);
                _mm_store_ps(lane_angle, ra);
                _mm_store_si128(reinterpret_cast<__m128i*>(lane_surface), surface);
                _mm_store_si128(reinterpret_cast<__m128i*>(lane_box), hit_box);
                _mm_store_si128(reinterpret_cast<__m128i*>(lane_axis), hit_axis);
                for (int l = 0; l < 4; ++l) {
                  hits[x + l].surface = Surface::kNone;
                  if (lane_angle[l] == 0.0f) continue;
                  record(x + l, Eigen::Vector3f(lane_dx[l], lane_dy[l], lane_dz[l]), lane_t[l],
                         lane_surface[l], lane_box[l], lane_axis[l], lane_angle[l]);
                }
              }
#endif
              for (; x < chunk_end; ++x) {
                const VehicleRay& r = row_rays[x];
                hits[x].surface = Surface::kNone;
                if (r.angle == 0.0f) continue;
                const Eigen::Vector3f d(cos_yaw * r.x - sin_yaw * r.y,
                                        sin_yaw * r.x + cos_yaw * r.y, r.z);
                const float ix = 1.0f / d.x(), iy = 1.0f / d.y(), iz = 1.0f / d.z();
                // Interior of the level: leave through floor, ceiling or a wall.
                const float tx = wall_x[d.x() > 0] * ix;
                const float ty = wall_y[d.y() > 0] * iy;
                const float tz = wall_z[d.z() > 0] * iz;
                float t = tx;
                int surface = 0;  // 0 wall x, 1 wall y, 2 floor/ceiling
                if (ty < t) t = ty, surface = 1;
                if (tz < t) t = tz, surface = 2;
                int hit_box = -1, hit_axis = 0;
                const size_t tile = tile_row + static_cast<size_t>(x / kTile);
                for (const int* bi = tiles.begin(tile); bi != tiles.end(tile); ++bi) {
                  const RelativeBox& b = boxes[*bi];
                  const float ax0 = b.lo[0] * ix, ax1 = b.hi[0] * ix;
                  const float ay0 = b.lo[1] * iy, ay1 = b.hi[1] * iy;
                  const float az0 = b.lo[2] * iz, az1 = b.hi[2] * iz;
                  const float nx = std::min(ax0, ax1), ny = std::min(ay0, ay1),
                              nz = std::min(az0, az1);
                  const float tnear = std::max(nx, std::max(ny, nz));
                  const float tfar = std::min(std::max(ax0, ax1),
                                              std::min(std::max(ay0, ay1), std::max(az0, az1)));
                  if (tnear <= tfar && tnear > 1e-4f && tnear < t) {
                    t = tnear;
                    hit_box = *bi;
                    hit_axis = tnear == nx ? 0 : (tnear == ny ? 1 : 2);
                  }
                }
                record(x, d, t, surface, hit_box, hit_axis, r.angle);
              }
              // Pass 2: the floor's concrete, shade and light, the lookups of every pixel
              // independent of the others.
              shadeFloorBase(hits, buf.floor_pixels.data(), floor_count, buf.albedo.data(),
                             buf.irradiance.data());
              // Pass 3: paint and text on the floor, then every other surface.
              shadeFloorMarkings(hits, buf.floor_pixels.data(), floor_count, buf.albedo.data());
              for (int x = chunk; x < chunk_end; ++x) {
                const PixelHit& h = hits[x];
                if (h.surface == Surface::kNone || h.surface == Surface::kFloor) continue;
                shadeOther(h, buf.albedo[static_cast<size_t>(x)],
                           buf.irradiance[static_cast<size_t>(x)]);
              }
              // Pass 4: exposure, vignetting, tone curve and sensor noise.
              const Eigen::Vector3f* albedo = buf.albedo.data();
              const float* irradiance = buf.irradiance.data();
              for (int x = chunk; x < chunk_end; ++x) {
                if (hits[x].surface == Surface::kNone) {
                  out[3 * x] = out[3 * x + 1] = out[3 * x + 2] = 0;
                  continue;
                }
                const float scale = irradiance[x] * exposure_scale * row_vignette[x];
                const float* n3 = row_noise + 3 * x;
#if defined(__SSE2__)
                // The three channels at once, the scalar loop's operations lane by lane: the
                // index clamp is done before truncating (the same for any value below 2^31),
                // packing saturates as the clamp to [0, 255] does.
                const __m128 rgb = _mm_loadu_ps(albedo[x].data());
                const __m128 bgr = _mm_shuffle_ps(rgb, rgb, _MM_SHUFFLE(3, 0, 1, 2));
                const __m128 index = _mm_min_ps(
                    _mm_max_ps(_mm_mul_ps(bgr, _mm_set1_ps(scale)), _mm_setzero_ps()), v_lut_max);
                alignas(16) int idx[4];
                _mm_store_si128(reinterpret_cast<__m128i*>(idx), _mm_cvttps_epi32(index));
                const __m128 tone = _mm_setr_ps(lut[idx[0]], lut[idx[1]], lut[idx[2]], 0.0f);
                const __m128i v =
                    _mm_cvtps_epi32(_mm_add_ps(tone, _mm_mul_ps(v_sigma, _mm_loadu_ps(n3))));
                const uint32_t bytes = static_cast<uint32_t>(_mm_cvtsi128_si32(
                    _mm_packus_epi16(_mm_packs_epi32(v, v), _mm_setzero_si128())));
                out[3 * x] = static_cast<uint8_t>(bytes);
                out[3 * x + 1] = static_cast<uint8_t>(bytes >> 8);
                out[3 * x + 2] = static_cast<uint8_t>(bytes >> 16);
#else
                for (int ch = 0; ch < 3; ++ch) {
                  // BGR output.
                  const int idx =
                      std::min(kLutSize - 1, static_cast<int>(albedo[x][2 - ch] * scale));
                  // saturate_cast without its branches (lamps clip, noise straddles the limits).
                  const int v = cvRound(lut[std::max(0, idx)] + sigma * n3[ch]);
                  out[3 * x + ch] = static_cast<uint8_t>(std::min(255, std::max(0, v)));
                }
#endif
              }
            }
          }
        },
        stripes);

    // The same blur the labels' legibility rule assumes (sim/legibility.h).
    const ImageBlur blur = imageBlur(light, cam);
    if (blur.defocus_sigma_px > 0.0)
      cv::GaussianBlur(img, img, cv::Size(0, 0), blur.defocus_sigma_px);
    if (blur.motion_length_px > 1.0)
      cv::blur(img, img, cv::Size(static_cast<int>(blur.motion_length_px), 1));
    return img;
  }

  // Floor albedo without markings (concrete x shade) and irradiance of the listed pixels,
  // four at a time where SSE2 is there (the same operations as bareFloorAlbedo).
  void shadeFloorBase(const PixelHit* hits, const int* pixels, int count, Eigen::Vector3f* albedo,
                      float* irradiance) const {
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
        if (!g.concrete.sampleNearestLevel4(
                _mm_mul_ps(px, v_ctpm), _mm_mul_ps(py, v_ctpm),
                _mm_mul_ps(
                    _mm_setr_ps(h[0]->footprint, h[1]->footprint, h[2]->footprint, h[3]->footprint),
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
  Eigen::Vector3f bareFloorAlbedo(const Eigen::Vector3f& p, float footprint_m) const {
    const float ctpm = static_cast<float>(g.concrete_texels_per_metre);
    const float stpm = static_cast<float>(g.shade_texels_per_metre);
    const float c = g.concrete.sampleNearestLevel(p.x() * ctpm, p.y() * ctpm, footprint_m * ctpm);
    const float shade = floor_shade_grid.at(p.x() * stpm - 0.5f, p.y() * stpm - 0.5f);
    return g.floor_albedo * (shade * (0.45f + 0.95f * c));
  }

  // Irradiance times this is the tone curve's index (before vignetting).
  float exposureScale() const { return light.exposure * (kLutSize - 1) / kLutMax; }

  // Painted lines and text decals over the floor albedo of the listed pixels.
  void shadeFloorMarkings(const PixelHit* hits, const int* pixels, int count,
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

  double floorInkContrast(size_t camera, const Eigen::Vector2d& pixel, int decal) const {
    const Decal& d = L.floor_decals.at(static_cast<size_t>(decal));
    const CameraRays& cr = (*rays).at(camera);
    const int x = std::clamp(static_cast<int>(std::lround(pixel.x())), 0, cr.width - 1);
    const int y = std::clamp(static_cast<int>(std::lround(pixel.y())), 0, cr.height - 1);
    const float vignette = cr.vignette[static_cast<size_t>(y) * cr.width + x];
    const Eigen::Vector3f centre =
        d.origin + 0.5f * d.size_u * d.axis_u + 0.5f * d.size_v * d.axis_v;
    // The bare floor under the text, the concrete averaged over a glyph's height.
    const Eigen::Vector3f floor = bareFloorAlbedo(centre, d.size_v);
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

  // Albedo and irradiance of a pixel on a box, the ceiling or a wall.
  void shadeOther(const PixelHit& h, Eigen::Vector3f& albedo, float& e) const {
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
};

Renderer::Renderer(const Garage& garage, int level, const geometry::Rig& rig,
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
