#pragma once
// Per-image text labels of the synthetic dataset: labels/<camera>/<timestamp>.json, and the
// same polygons as ICDAR-2015 text lines (x1,y1,...,x4,y4,transcription). Schema:
// {"camera": "front", "timestamp": 12.35, "width": 1280, "height": 800,
//  "instances": [{"polygon": [[x, y] x4], "text": "B2-117", "class_id": 1,
//                 "class": "parking_number", "occluded_fraction": 0.0, "truncated": false,
//                 "legible": true, "landmark_id": "B2-117", "rotation_deg": 37.0,
//                 "visible_polygon": [[x, y] x4]}]}
// Polygons are in pixels (OpenCV convention), reading order: top-left, top-right,
// bottom-right, bottom-left of the text as it reads. rotation_deg is the angle of the
// reading direction in the image (0 = left to right, 180 = upside down). "legible" is false
// for text too thin in the image to be read (ICDAR's "###", don't care); absent means true.
// "visible_polygon", only on text cut by the image's edge or partly hidden (by a car, a pillar
// or the recording car's own body), is the part that the image shows: the corners of the
// text's seen span, projected through the lens. A cut text's whole corners lie outside the
// image, where a fisheye bends the text far from the straight quad between them, and a
// detector can box only the ink that shows, so the visible part is what a detection is matched
// against.
#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "geometry/text_polygon.h"
#include "map/landmark.h"

namespace parkloc::io {

struct LabelInstance {
  std::array<Eigen::Vector2d, 4> polygon;
  std::string text;
  map::TextClass cls = map::TextClass::kParkingNumber;
  double occluded_fraction = 0.0;
  bool truncated = false;
  bool legible = true;  // false: too thin to read, "don't care" in the metrics
  std::string landmark_id;
  double rotation_deg = 0.0;
  std::optional<geometry::TextPolygon> visible_polygon;  // text cut or partly hidden
  // How worn the paint is, 0 (intact) to 1 (mostly erased): the simulator's wear of painted
  // floor text; 0 for other text and in labels without the field.
  double paint_wear = 0.0;
  // Painted floor text: the signal-to-noise ratio of one reading feature of its ink against
  // the floor (sim::featureSnr; not legible below 5). Absent for other text and in labels
  // without the field.
  std::optional<double> ink_snr;
};

struct ImageLabels {
  std::string camera;
  double timestamp = 0.0;
  int width = 0;
  int height = 0;
  std::vector<LabelInstance> instances;
};

ImageLabels loadLabels(const std::string& path);  // throws InputError
void saveLabels(const ImageLabels& labels, const std::string& path);
// ICDAR-2015 ground-truth text file, text cut by the image's edge by its visible polygon;
// '###' marks instances to ignore (occluded >= 0.5 or not legible).
void saveIcdarLabels(const ImageLabels& labels, const std::string& path);

}  // namespace parkloc::io
