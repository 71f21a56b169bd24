#pragma once
// Putting a built map into a surveyed frame: the anchors' known positions against the built
// landmarks of the same text, fitted by least squares as a rigid transform or a similarity
// (which also corrects the drive's scale, when the odometry's wheel radius is off), and the
// whole map (landmarks, their sizes and sigmas, the drive) moved by it. The residual of each
// anchor is reported: a large one is a wrong survey or a wrong reading.
#include <string>
#include <vector>

#include "geometry/planar_fit.h"
#include "io/anchors_csv.h"
#include "mapping/landmark_estimate.h"

namespace parkloc::mapping {

struct AnchorFit {
  geometry::PlanarFit fit;             // built map -> anchors' frame
  std::vector<std::string> used;       // anchors matched, in the order of fit.residuals
  std::vector<std::string> unmatched;  // anchors the built map has no landmark for
};

// Throws InputError when fewer than two anchors match a landmark.
AnchorFit fitAnchors(const std::vector<LandmarkEstimate>& landmarks,
                     const std::vector<io::Anchor>& anchors, bool with_scale);

// Moves a landmark and scales its size and sigmas as `fit` says.
void applyFit(const geometry::PlanarFit& fit, LandmarkEstimate& landmark);
// The same for a vehicle pose.
geometry::Pose2 applyFit(const geometry::PlanarFit& fit, const geometry::Pose2& pose);

}  // namespace parkloc::mapping
