#pragma once
// One text instance matched to a map landmark: its four image corners and the landmark's
// four corners, both in reading order (top-left, top-right, bottom-right, bottom-left), so
// corner i of the image belongs to corner i of the map.
#include <Eigen/Core>
#include <array>
#include <string>

#include "map/landmark.h"

namespace parkloc::localize {

struct LandmarkObservation {
  int camera = -1;  // index into Rig::cameras
  std::string landmark_id;
  std::array<Eigen::Vector2d, 4> pixels;
  // Map x, y; z is the height above the floor the vehicle stands on.
  std::array<Eigen::Vector3d, 4> map_corners;
  int tag = -1;  // caller's index (e.g. into the association list)
  // false: only the polygon's centre is a measurement (2 residuals), for detectors whose
  // boxes hold the text but whose corners are not the text's (padded, unsheared boxes of
  // text seen at a grazing angle); the centre stays where the ink is.
  bool use_corners = true;
  // What the map states of the landmark's accuracy (empty: the solver's assumption,
  // SolverOptions::assumed_map_*).
  map::MapAccuracy accuracy;
  // Recognised by OCR as a text the map has at this landmark's place alone. False for a
  // corner fit at the place the filter predicts (it labels the ink with the text it expects
  // without reading it), for a second opinion and for a text the map has at several places
  // (the predicted pose chose among them): none of them can tell that the filter is at the
  // wrong place (track_lifecycle.h, the tentative track).
  bool read = true;
};

// What a text's polygon measures in the solver. Corners: all four corners (exact polygons,
// e.g. ground-truth labels). Centre: only the polygon's centre (detector boxes are padded
// and cannot follow the shear of floor text seen at a grazing angle, but they stay centred
// on the ink). Auto: corners for instances that come with the frame (oracle), the centre
// for those of the injected spotter.
enum class PolygonModel { kAuto, kCorners, kCentre };

}  // namespace parkloc::localize
