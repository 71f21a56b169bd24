#pragma once
// Checks of one text-to-landmark association against the predicted pose (beyond the
// paper): a number that is in the map but far from where the prediction puts it is
// rejected (Mahalanobis gating in the image), and so is a reading whose polygon runs the
// wrong way round (a 180-degree reading would otherwise turn the pose by 180 degrees).
#include <Eigen/Core>
#include <optional>

#include "geometry/pose.h"
#include "geometry/rig.h"
#include "localize/landmark_observation.h"

namespace parkloc::localize {

struct GateOptions {
  // Pixel noise of an observed text centre on top of the pose uncertainty (OCR polygon
  // jitter, map survey error).
  double centre_sigma_px = 6.0;
  // Floor on the position uncertainty used for gating: an error of this many metres is
  // never gated (3 sigma).
  double min_radius_m = 0.5;
};

struct GateResult {
  // Squared Mahalanobis distance (2 dof) of the observed text centre from its prediction.
  double mahalanobis2 = 0.0;
  // The observed reading direction points the same way as the predicted one (within 90
  // degrees).
  bool reading_order_agrees = true;
};

// Empty when the landmark does not project into the camera at the predicted pose (it
// cannot be where it was seen).
std::optional<GateResult> gateObservation(const geometry::RigCamera& camera,
                                          const LandmarkObservation& observation,
                                          const geometry::Pose2& predicted,
                                          const Eigen::Matrix3d& covariance,
                                          const GateOptions& options = {});

}  // namespace parkloc::localize
