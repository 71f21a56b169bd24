#pragma once
// A synthetic garage aisle with exactly known landmarks, and exact (or noisy) text
// instances of what the default rig sees from a given pose. Shared by the localize tests.
#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "geometry/pose.h"
#include "geometry/rig.h"
#include "localize/floor_heights.h"
#include "localize/landmark_observation.h"
#include "localize/pipeline.h"
#include "map/hd_map.h"
#include "ocr/text_spotter.h"

namespace parkloc::localize::testing {

// Two rows of painted parking numbers (y = +-4.5 m, every 2.5 m from x = -20 to 60) and
// pillar text on pillars between the bays (y = +-3.2 m), all on level "B2".
inline map::HdMap aisleMap() {
  std::vector<map::Landmark> landmarks;
  int number = 100;
  for (double x = -20.0; x <= 60.0; x += 2.5) {
    for (int side : {1, -1}) {
      map::Landmark l;
      l.text = "B2-" + std::to_string(++number);
      l.id = l.text;
      l.cls = map::TextClass::kParkingNumber;
      l.level = "B2";
      l.position = {x, side * 4.5, 0.0};
      // Reads towards the aisle's far side, so that a driver in the aisle reads it upright.
      l.heading = side > 0 ? -M_PI / 2 : M_PI / 2;
      l.width = 0.9;
      l.height = 0.4;
      l.surface = map::Surface::kGround;
      landmarks.push_back(l);
    }
  }
  int pillar = 0;
  for (double x = -18.75; x <= 60.0; x += 7.5) {
    for (int side : {1, -1}) {
      map::Landmark l;
      l.text = "P" + std::to_string(++pillar);
      l.id = "pillar-" + l.text;
      l.cls = map::TextClass::kPillar;
      l.level = "B2";
      l.position = {x, side * 3.2, 1.4};
      l.heading = side > 0 ? 0.0 : M_PI;  // reads left to right seen from the aisle
      l.normal = {0.0, -static_cast<double>(side), 0.0};
      l.width = 0.5;
      l.height = 0.25;
      l.surface = map::Surface::kVertical;
      landmarks.push_back(l);
    }
  }
  return map::HdMap(landmarks, "aisle");
}

struct SpotOptions {
  double pixel_noise = 0.0;  // Gaussian, per corner coordinate
  double min_side_px = 12.0;
  double max_range_m = 14.0;
  bool pillars = true;
};

// Every landmark the camera sees whole from `map_from_vehicle`: polygon in reading order.
inline std::vector<ocr::TextInstance> spotExactly(const geometry::RigCamera& camera,
                                                  const map::HdMap& map,
                                                  const geometry::Pose2& map_from_vehicle,
                                                  const SpotOptions& options = {},
                                                  std::mt19937* rng = nullptr) {
  const geometry::Rigid3 camera_from_map =
      (map_from_vehicle.toRigid3() * camera.vehicle_from_camera).inverse();
  std::normal_distribution<double> noise(0.0, options.pixel_noise);
  std::vector<ocr::TextInstance> out;
  for (const auto& l : map.landmarks()) {
    if (!options.pillars && l.cls == map::TextClass::kPillar) continue;
    if ((l.position.head<2>() - map_from_vehicle.translation()).norm() > options.max_range_m)
      continue;
    const Eigen::Vector3d camera_in_map = camera_from_map.inverse().translation();
    if (l.surface == map::Surface::kVertical && l.normal.dot(camera_in_map - l.position) <= 0.0)
      continue;
    ocr::TextInstance t;
    bool ok = true;
    const auto corners = l.corners();
    for (int i = 0; i < 4 && ok; ++i) {
      const auto p = camera.model.project(camera_from_map * corners[i]);
      if (!p || !camera.model.inImage(*p, 2.0)) {
        ok = false;
        break;
      }
      Eigen::Vector2d q = *p;
      if (rng && options.pixel_noise > 0.0) q += Eigen::Vector2d(noise(*rng), noise(*rng));
      t.polygon[i] = cv::Point2f(static_cast<float>(q.x()), static_cast<float>(q.y()));
    }
    if (!ok) continue;
    double longest = 0.0;
    for (int i = 0; i < 4; ++i)
      longest =
          std::max(longest, static_cast<double>(cv::norm(t.polygon[(i + 1) % 4] - t.polygon[i])));
    if (longest < options.min_side_px) continue;
    t.text = t.raw_text = l.text;
    t.cls = l.cls;
    t.lexicon_match = true;
    t.detection_score = t.recognition_score = t.class_score = 1.f;
    out.push_back(t);
  }
  return out;
}

// What a spotter asked for `request` reads of `all`: everything on a full frame, else the
// texts of the requested regions.
inline std::vector<ocr::TextInstance> inRequestedRegions(const std::vector<ocr::TextInstance>& all,
                                                         const ocr::SpotRequest& request) {
  if (request.regions.empty()) return all;
  std::vector<ocr::TextInstance> out;
  for (const auto& t : all)
    for (const auto& r : request.regions)
      if (r.expected_texts.front() == t.text) out.push_back(t);
  return out;
}

// The same as solver observations (polygon corner i <-> landmark corner i).
inline std::vector<LandmarkObservation> observeExactly(const geometry::Rig& rig,
                                                       const map::HdMap& map,
                                                       const geometry::Pose2& map_from_vehicle,
                                                       const SpotOptions& options = {},
                                                       std::mt19937* rng = nullptr) {
  const FloorHeights floors(map);
  std::vector<LandmarkObservation> out;
  for (size_t c = 0; c < rig.cameras.size(); ++c) {
    for (const auto& t : spotExactly(rig.cameras[c], map, map_from_vehicle, options, rng)) {
      const auto* l = map.findByText(t.text).front();
      LandmarkObservation o;
      o.camera = static_cast<int>(c);
      o.landmark_id = l->id;
      for (int i = 0; i < 4; ++i) o.pixels[i] = {t.polygon[i].x, t.polygon[i].y};
      o.map_corners = floors.cornersAboveFloor(*l);
      o.tag = static_cast<int>(out.size());
      out.push_back(o);
    }
  }
  return out;
}

// A frame set at time t for a spotter that ignores the pixels: a blank image of each rig
// camera's calibrated size (the pipeline skips any other) and one odometry sample of the
// given speed (straight ahead).
inline FrameInput placeholderFrame(const geometry::Rig& rig, double t, double speed) {
  FrameInput in;
  in.timestamp = t;
  for (const auto& camera : rig.cameras)
    in.cameras.push_back(
        {camera.name, cv::Mat(camera.model.height, camera.model.width, CV_8UC3), {}, {}});
  OdometrySample odo;
  odo.timestamp = t;
  odo.speed = speed;
  in.odometry.push_back(odo);
  return in;
}

}  // namespace parkloc::localize::testing
