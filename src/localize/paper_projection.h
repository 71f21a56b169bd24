#pragma once
// The paper's positioning (OCR-RTPS sections 3.4 and 3.5): the centre of a text's box goes
// through the camera's ground homography to give the parking number's position relative to
// the vehicle; the HD map gives its absolute position; together they give the vehicle's.
// MCRP averages the relative positions of one landmark over the cameras that see it; MCAP
// averages the vehicle positions over all landmarks.
#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "geometry/camera_model.h"
#include "geometry/ground_projection.h"

namespace parkloc::localize {

// Centre of a text polygon: the mean of its corners, or the centre of its axis-aligned
// bounding box (the paper's box).
Eigen::Vector2d textCentre(const std::array<Eigen::Vector2d, 4>& polygon, bool from_polygon);

struct PaperObservation {
  int camera = -1;
  std::string landmark_id;
  Eigen::Vector2d map_position = Eigen::Vector2d::Zero();  // the landmark's centre (map x, y)
  double map_heading = 0.0;                                // its reading direction in the map
  Eigen::Vector2d relative = Eigen::Vector2d::Zero();      // text centre, vehicle frame
  // Reading direction of the text in the vehicle frame (angle), from the homography of the
  // polygon's left and right edge midpoints; empty when they do not reach the ground.
  std::optional<double> reading_angle;
};

// Empty when the centre does not reach the ground (above the horizon or behind).
std::optional<PaperObservation> paperObserve(const geometry::GroundHomography& homography,
                                             const geometry::CameraModel& model,
                                             const std::array<Eigen::Vector2d, 4>& polygon,
                                             bool centre_from_polygon);

struct PaperFix {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  int landmarks = 0;     // landmarks that contributed
  int observations = 0;  // camera observations that contributed
};

// Vehicle position for heading `yaw`: with MCRP the relative positions of one landmark are
// averaged over its cameras (else the first camera's is used); with MCAP the positions
// from all landmarks are averaged (else only the nearest landmark's, the most precise).
std::optional<PaperFix> paperFuse(const std::vector<PaperObservation>& observations, double yaw,
                                  bool mcrp, bool mcap);

// Heading from the texts' reading directions against their map headings (circular mean);
// empty when no observation has a reading direction.
std::optional<double> headingFromTextDirections(const std::vector<PaperObservation>& obs);

}  // namespace parkloc::localize
