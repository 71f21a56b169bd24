#include "localize/roi_prediction.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "localize/pose_solver.h"

namespace parkloc::localize {

std::array<Eigen::Vector2d, 4> growQuad(const std::array<Eigen::Vector2d, 4>& quad,
                                        double distance) {
  const Eigen::Vector2d centre = 0.25 * (quad[0] + quad[1] + quad[2] + quad[3]);
  std::array<Eigen::Vector2d, 4> normals;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector2d edge = quad[(i + 1) % 4] - quad[i];
    Eigen::Vector2d n(edge.y(), -edge.x());
    const double length = n.norm();
    if (length < 1e-12) {
      normals[i] = Eigen::Vector2d::Zero();
      continue;
    }
    n /= length;
    if (n.dot(0.5 * (quad[i] + quad[(i + 1) % 4]) - centre) < 0.0) n = -n;
    normals[i] = n;
  }
  std::array<Eigen::Vector2d, 4> out;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector2d& a = normals[(i + 3) % 4];  // edge ending at corner i
    const Eigen::Vector2d& b = normals[i];            // edge starting at corner i
    const double denominator = 1.0 + a.dot(b);
    // Mitre: the corner moves so that both edges move by `distance`; capped for sharp ones.
    const Eigen::Vector2d mitre =
        denominator > 0.25 ? Eigen::Vector2d((a + b) / denominator) : Eigen::Vector2d(a + b);
    out[i] = quad[i] + distance * mitre;
  }
  return out;
}

std::vector<ocr::RegionOfInterest> predictRegions(const geometry::RigCamera& camera,
                                                  const std::vector<const map::Landmark*>& nearby,
                                                  const FloorHeights& floors,
                                                  const geometry::Pose2& pose,
                                                  const Eigen::Matrix3d& covariance,
                                                  const RoiOptions& options) {
  std::vector<ocr::RegionOfInterest> regions;
  for (const map::Landmark* landmark : nearby) {
    const auto corners = floors.cornersAboveFloor(*landmark);
    std::array<Eigen::Vector2d, 4> quad;
    double grow_sigma = 0.0;
    bool ok = true;
    for (int i = 0; i < 4 && ok; ++i) {
      const auto p = projectMapCorner(camera, pose, corners[i]);
      if (!p) {
        ok = false;
        break;
      }
      quad[i] = p->pixel;
      const Eigen::Matrix2d pixel_covariance =
          p->J_pixel_pose * covariance * p->J_pixel_pose.transpose();
      const double largest =
          Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(pixel_covariance, Eigen::EigenvaluesOnly)
              .eigenvalues()
              .maxCoeff();
      grow_sigma = std::max(grow_sigma, std::sqrt(std::max(largest, 0.0)));
    }
    if (!ok) continue;
    const Eigen::Vector2d centre = 0.25 * (quad[0] + quad[1] + quad[2] + quad[3]);
    if (!camera.model.inImage(centre)) continue;
    double longest = 0.0;
    for (int i = 0; i < 4; ++i) longest = std::max(longest, (quad[(i + 1) % 4] - quad[i]).norm());
    if (longest < options.min_size_px) continue;
    const double grow = options.margin_px + options.sigma_scale * grow_sigma;
    if (grow > options.max_grow_px) continue;
    // A polygon seen edge-on (pillar text from the side) may fold; skip it.
    const auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
      return a.x() * b.y() - a.y() * b.x();
    };
    double area = 0.0;
    for (int i = 0; i < 4; ++i) area += 0.5 * cross(quad[i], quad[(i + 1) % 4]);
    if (std::abs(area) < 1.0) continue;

    ocr::RegionOfInterest roi;
    const auto grown = growQuad(quad, grow);
    for (int i = 0; i < 4; ++i)
      roi.polygon[i] =
          cv::Point2f(static_cast<float>(grown[i].x()), static_cast<float>(grown[i].y()));
    roi.expected_texts.push_back(landmark->text);
    regions.push_back(std::move(roi));
  }
  return regions;
}

}  // namespace parkloc::localize
