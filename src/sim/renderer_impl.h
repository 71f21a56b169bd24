#pragma once
// The renderer's state and passes (sim/renderer.h's Renderer::Impl). One frame of one camera
// runs, per chunk of a row: tracing (render_trace.cc: which surface each pixel's ray meets),
// floor shading (render_floor.cc: concrete, stains, paint and text), the other surfaces
// (render_surfaces.cc: pillars, cars, walls, ceiling and lamps) and the sensor
// (render_sensor.cc: exposure, vignetting, tone curve, noise, then defocus and motion blur).
// The tables they read are built once per level and drive (renderer.cc). Internal to the sim
// module.
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "geometry/pose.h"
#include "geometry/rig.h"
#include "sim/garage.h"
#include "sim/render_support.h"
#include "sim/renderer.h"

namespace parkloc::sim {

struct Renderer::Impl {
  using CellLists = detail::CellLists;
  using FloatGrid = detail::FloatGrid;

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
  // The appearance's floor wear and puddles (empty maps: none), and whether a pass over the
  // floor's finish is needed at all.
  FloatGrid grime_grid, wetness_grid;
  bool floor_finish = false;
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

  // Scene tables (renderer.cc): the lamps that are on, light maps, paint mask, decal and lamp
  // grids, the rays in the vehicle frame, the car's own body, the tone curve.
  Impl(const Garage& garage, const GarageLevel& level, const geometry::Rig& r,
       std::shared_ptr<const std::vector<CameraRays>> ry, const LightingOptions& li);
  void addToGrid(std::vector<std::vector<int>>& grid, const Eigen::Vector2f& lo,
                 const Eigen::Vector2f& hi, int index) const;
  size_t cellIndex(float x, float y) const {
    const int ix = std::clamp(static_cast<int>(x), 0, grid_w - 1);
    const int iy = std::clamp(static_cast<int>(y), 0, grid_h - 1);
    return static_cast<size_t>(iy) * grid_w + ix;
  }
  bool paintNear(float x, float y) const {
    const int mx = std::clamp(static_cast<int>(x * 2.0f), 0, paint_mask_w - 1);
    const int my = std::clamp(static_cast<int>(y * 2.0f), 0, paint_mask_h - 1);
    return paint_mask[static_cast<size_t>(my) * paint_mask_w + mx] != 0;
  }

  // Tracing (render_trace.cc).
  CellLists cullBoxes(size_t ci, const geometry::Rigid3& map_from_camera) const;
  cv::Mat renderCamera(size_t ci, const geometry::Pose2& pose, uint64_t seed) const;

  // The floor (render_floor.cc).
  float decalCoverage(const Decal& d, const Eigen::Vector3f& p, float footprint_m) const;
  void shadeFloorBase(const PixelHit* hits, const int* pixels, int count, Eigen::Vector3f* albedo,
                      float* irradiance) const;
  Eigen::Vector3f bareFloorAlbedo(const Eigen::Vector3f& p, float footprint_m) const;
  void shadeFloorMarkings(const PixelHit* hits, const int* pixels, int count,
                          Eigen::Vector3f* albedo) const;
  double floorInkContrast(size_t camera, const Eigen::Vector2d& pixel, int decal) const;
  // The floor's wear over its paint, and a glossy floor's mirrored lamps and ceiling
  // (render_floor_finish.cc); only when the garage has either.
  void shadeFloorFinish(const PixelHit* hits, const int* pixels, int count, Eigen::Vector3f* albedo,
                        const float* irradiance) const;
  float mirroredLamps(const Eigen::Vector2f& q, const Eigen::Vector2f& along, float blur_m,
                      float blur_along_m) const;

  // Every other surface (render_surfaces.cc).
  float verticalLightExact(const Eigen::Vector3f& p, const Eigen::Vector2f& n) const;
  float verticalLight(const Eigen::Vector3f& p, const Eigen::Vector3f& n) const;
  static Eigen::Vector3f carBodyAlbedo(const Box& b, const Eigen::Vector3f& p,
                                       const Eigen::Vector3f& n);
  Eigen::Vector3f boxAlbedo(const Box& b, const Eigen::Vector3f& p, const Eigen::Vector3f& d,
                            const Eigen::Vector3f& n, float footprint) const;
  void shadeOther(const PixelHit& h, Eigen::Vector3f& albedo, float& e) const;

  // The sensor (render_sensor.cc).
  // Irradiance times this is the tone curve's index (before vignetting).
  float exposureScale() const { return light.exposure * (kLutSize - 1) / kLutMax; }
  void buildToneCurve();
  void exposePixels(const PixelHit* hits, const Eigen::Vector3f* albedo, const float* irradiance,
                    const float* vignette, const float* noise, int begin, int end,
                    uint8_t* out) const;
  void applyLensBlur(cv::Mat& img, const geometry::RigCamera& cam) const;
};

}  // namespace parkloc::sim
