#pragma once
// How one landmark's map error moves a pose fix. A surveyed map places each text with an
// error e (x, y, heading, log width, log height) that every frame seeing the text repeats; a
// fix solved on that map is off by J_fix_map e beyond its pixel noise. The filter keeps e of
// the landmarks in view as states (pose_ekf.h), so that consecutive fixes of one landmark
// share its error instead of averaging it as if it were noise.
#include <Eigen/Core>
#include <string>

namespace parkloc::localize {

struct MapErrorTerm {
  std::string landmark_id;
  // d fix (x, y, yaw) / d the landmark's map error (x, y, heading, log width, log height).
  Eigen::Matrix<double, 3, 5> J_fix_map = Eigen::Matrix<double, 3, 5>::Zero();
  // The map's stated variances of that error (its covariance is diagonal).
  Eigen::Matrix<double, 5, 1> variance = Eigen::Matrix<double, 5, 1>::Zero();
};

}  // namespace parkloc::localize
