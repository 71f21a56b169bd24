#pragma once
// Least-squares fit of one set of planar points onto another: the rigid SE(2) transform, or
// the similarity (rotation, translation and one scale), that minimises the sum of squared
// distances between corresponding points (Umeyama 1991, closed form through the SVD of the
// cross-covariance). Used to put a built map into a surveyed frame (anchors) and to align
// two maps before comparing them.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "geometry/pose.h"

namespace parkloc::geometry {

struct PlanarFit {
  Pose2 to_from_from;  // the rotation and translation
  double scale = 1.0;  // 1 for a rigid fit
  // Per point pair, |scale R p + t - q| (metres), in input order.
  std::vector<double> residuals;
  double rms = 0.0;

  Eigen::Vector2d apply(const Eigen::Vector2d& p) const {
    return scale * (to_from_from.rotation() * p) + to_from_from.translation();
  }
};

// Empty with fewer than two pairs, or when the `from` points coincide (no rotation is
// defined). `with_scale`: a similarity; else rigid.
std::optional<PlanarFit> fitPlanar(const std::vector<Eigen::Vector2d>& from,
                                   const std::vector<Eigen::Vector2d>& to, bool with_scale);

}  // namespace parkloc::geometry
