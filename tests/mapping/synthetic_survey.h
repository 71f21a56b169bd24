#pragma once
// A survey drive made up in code: the default rig driving straight along an aisle past floor
// numbers on both sides, with the exact image corners of every number each camera sees.
#include <vector>

#include "geometry/rig.h"
#include "localize/pose_solver.h"
#include "mapping/landmark_estimate.h"
#include "mapping/sightings.h"
#include "mapping/survey_poses.h"

namespace parkloc::mapping::testing {

struct SyntheticSurvey {
  geometry::Rig rig = geometry::defaultRig();
  std::vector<LandmarkEstimate> truth;
  std::vector<geometry::Pose2> poses;  // true map_from_vehicle per frame set
  std::vector<Sighting> sightings;
};

inline SyntheticSurvey makeSurvey(int frames = 40, double step_m = 0.25) {
  SyntheticSurvey s;
  const char* texts[] = {"101", "102", "103", "104", "201", "202", "203"};
  for (int i = 0; i < 7; ++i) {
    LandmarkEstimate l;
    l.text = texts[i];
    const bool left = i < 4;
    l.parameters = {1.5 + 2.5 * (left ? i : i - 4) + (left ? 0.0 : 1.2), left ? 3.2 : -3.0,
                    left ? M_PI : 0.0, 0.9, 0.45};
    s.truth.push_back(l);
  }
  for (int f = 0; f < frames; ++f)
    s.poses.emplace_back(step_m * f, 0.05 * std::sin(0.2 * f), 0.02 * f / frames);
  for (int f = 0; f < frames; ++f)
    for (size_t c = 0; c < s.rig.cameras.size(); ++c)
      for (const LandmarkEstimate& l : s.truth) {
        double corners[4][3];
        floorCorners(l.parameters.data(), corners);
        Sighting sighting;
        sighting.frame = static_cast<size_t>(f);
        sighting.camera = static_cast<int>(c);
        sighting.text = l.text;
        sighting.recognition_score = 0.9;
        bool seen = true;
        for (int k = 0; k < 4 && seen; ++k) {
          const auto p = localize::projectMapCorner(
              s.rig.cameras[c], s.poses[f],
              Eigen::Vector3d(corners[k][0], corners[k][1], corners[k][2]));
          seen = p && s.rig.cameras[c].model.inImage(p->pixel, 20.0) &&
                 (Eigen::Vector2d(corners[k][0], corners[k][1]) - s.poses[f].translation()).norm() <
                     7.0;
          if (seen) sighting.pixels[k] = p->pixel;
        }
        if (seen) s.sightings.push_back(sighting);
      }
  return s;
}

// The odometry between the true poses, with a yaw-rate bias and a wheel-scale error; frame
// sets 0.1 s apart.
inline SurveyPoses biasedOdometry(const std::vector<geometry::Pose2>& poses, double scale,
                                  double yaw_per_step) {
  SurveyPoses out;
  out.map_from_vehicle.push_back(poses.front());
  for (size_t i = 0; i < poses.size(); ++i) out.timestamps.push_back(0.1 * static_cast<double>(i));
  for (size_t i = 1; i < poses.size(); ++i) {
    const geometry::Pose2 m = poses[i - 1].inverse() * poses[i];
    out.motion.emplace_back(scale * m.x, scale * m.y, m.yaw + yaw_per_step);
    out.map_from_vehicle.push_back(out.map_from_vehicle.back() * out.motion.back());
  }
  return out;
}

}  // namespace parkloc::mapping::testing
