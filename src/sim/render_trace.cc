#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <opencv2/core/utility.hpp>
#include <optional>

#include "sim/renderer_impl.h"

namespace parkloc::sim {

using detail::CellLists;
using detail::kChunk;
using detail::kInf;
using detail::kTile;
using detail::XorShift;
#if defined(__SSE2__)
using detail::laneSelect;
using detail::laneSelectInt;
#endif

namespace {

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

// Boxes that may cover each 16x16 tile of camera ci's image, as flat lists per tile.
CellLists Renderer::Impl::cullBoxes(size_t ci, const geometry::Rigid3& map_from_camera) const {
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

cv::Mat Renderer::Impl::renderCamera(size_t ci, const geometry::Pose2& pose, uint64_t seed) const {
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
                const __m128 hit = _mm_and_ps(
                    _mm_and_ps(_mm_cmple_ps(tnear, tfar), _mm_cmpgt_ps(tnear, _mm_set1_ps(1e-4f))),
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
              const Eigen::Vector3f d(cos_yaw * r.x - sin_yaw * r.y, sin_yaw * r.x + cos_yaw * r.y,
                                      r.z);
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
                const float tfar =
                    std::min(std::max(ax0, ax1), std::min(std::max(ay0, ay1), std::max(az0, az1)));
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
            if (floor_finish)
              shadeFloorFinish(hits, buf.floor_pixels.data(), floor_count, buf.albedo.data(),
                               buf.irradiance.data());
            for (int x = chunk; x < chunk_end; ++x) {
              const PixelHit& h = hits[x];
              if (h.surface == Surface::kNone || h.surface == Surface::kFloor) continue;
              shadeOther(h, buf.albedo[static_cast<size_t>(x)],
                         buf.irradiance[static_cast<size_t>(x)]);
            }
            // Pass 4: exposure, vignetting, tone curve and sensor noise.
            exposePixels(hits, buf.albedo.data(), buf.irradiance.data(), row_vignette, row_noise,
                         chunk, chunk_end, out);
          }
        }
      },
      stripes);

  applyLensBlur(img, cam);
  return img;
}

}  // namespace parkloc::sim
