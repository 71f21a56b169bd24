#pragma once
// A landmark of the map being built: a parking number painted on the floor, its five
// parameters (the estimation's unknowns) and what the build learnt about it.
#include <array>
#include <optional>
#include <string>

#include "map/landmark.h"

namespace parkloc::mapping {

// Indices into LandmarkEstimate::parameters.
enum LandmarkParameter { kX = 0, kY = 1, kHeading = 2, kWidth = 3, kHeight = 4 };

struct LandmarkEstimate {
  std::string text;
  map::TextClass cls = map::TextClass::kParkingNumber;
  // Map x, y of the centre (metres), reading direction (radians from +x), width along it and
  // height across it (metres): as map::Landmark has them.
  std::array<double, 5> parameters{};
  // From the estimation's covariance (1 sigma): per axis of the centre, and the heading.
  std::optional<double> position_sigma;
  std::optional<double> heading_sigma;
  int sightings = 0;        // camera readings that agree on `text`
  int frame_sets = 0;       // distinct frame sets among them
  int misreads = 0;         // readings at its place outvoted by `text`
  double rms_px = 0.0;      // corner reprojection error after the estimation
  double median_px = 0.0;   // its median over the corners: what most of them say
  int outlier_corners = 0;  // corners the robust loss mostly ignores
  // Set by merging: the existing map had it elsewhere (metres moved), or not at all.
  std::optional<double> moved_m;
  bool added = false;

  // The map's view of it (id "<level>:<text>", or the text without a level).
  map::Landmark toLandmark(const std::string& level) const;
};

// The corners of a floor text with these parameters (z = 0), in reading order, as
// map::Landmark::corners gives them.
template <typename T>
void floorCorners(const T* p, T corners[4][3]) {
  using std::cos;
  using std::sin;
  const T c = cos(p[kHeading]), s = sin(p[kHeading]);
  const T hw = T(0.5) * p[kWidth], hh = T(0.5) * p[kHeight];
  // Reading direction (c, s); the top of the glyphs 90 degrees counter-clockwise of it.
  constexpr double kWidthSign[4] = {-1.0, 1.0, 1.0, -1.0};
  constexpr double kHeightSign[4] = {1.0, 1.0, -1.0, -1.0};
  for (int i = 0; i < 4; ++i) {
    corners[i][0] = p[kX] + kWidthSign[i] * hw * c - kHeightSign[i] * hh * s;
    corners[i][1] = p[kY] + kWidthSign[i] * hw * s + kHeightSign[i] * hh * c;
    corners[i][2] = T(0.0);
  }
}

}  // namespace parkloc::mapping
