#pragma once
// Map-guided spotting (beyond the paper, for real time): from the predicted pose and its
// covariance, project the map's nearby text into a camera and ask the spotter to look only
// there, for the texts expected there.
#include <Eigen/Core>
#include <vector>

#include "geometry/pose.h"
#include "geometry/rig.h"
#include "localize/floor_heights.h"
#include "localize/region_budget.h"
#include "map/landmark.h"
#include "ocr/text_spotter.h"

namespace parkloc::localize {

struct RoiOptions {
  double margin_px = 12.0;     // added around every predicted polygon
  double sigma_scale = 3.0;    // the polygon grows by this many pixel sigmas of the pose
  double min_size_px = 8.0;    // predicted text smaller than this (longest side) is skipped
  double max_grow_px = 200.0;  // beyond this the prediction is useless: skip the landmark
};

// Regions for one camera. Landmarks whose corners do not all project, whose centre falls
// outside the image, or that are too small or too uncertain are skipped.
std::vector<ocr::RegionOfInterest> predictRegions(const geometry::RigCamera& camera,
                                                  const std::vector<const map::Landmark*>& nearby,
                                                  const FloorHeights& floors,
                                                  const geometry::Pose2& pose,
                                                  const Eigen::Matrix3d& covariance,
                                                  const RoiOptions& options = {});

// The same regions with the landmark id and the predicted text's size, which the per-frame
// region budget (localize/region_budget.h) ranks them by.
std::vector<RegionCandidate> predictRegionCandidates(
    const geometry::RigCamera& camera, const std::vector<const map::Landmark*>& nearby,
    const FloorHeights& floors, const geometry::Pose2& pose, const Eigen::Matrix3d& covariance,
    const RoiOptions& options = {});

// The rectangle aligned with a text quad's reading direction that holds the quad, grown
// by `margin` pixels on every side; corners in reading order (top-left first). Robust to
// the folded, near-degenerate quads of text seen almost edge-on.
std::array<Eigen::Vector2d, 4> readingAlignedBox(const std::array<Eigen::Vector2d, 4>& quad,
                                                 double margin);

}  // namespace parkloc::localize
