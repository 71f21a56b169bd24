#include "localize/roi_prediction.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "localize/pose_solver.h"

namespace parkloc::localize {

std::array<Eigen::Vector2d, 4> readingAlignedBox(const std::array<Eigen::Vector2d, 4>& quad,
                                                 double margin) {
  Eigen::Vector2d along = 0.5 * (quad[1] + quad[2] - quad[0] - quad[3]);
  if (along.norm() < 1e-9) along = Eigen::Vector2d::UnitX();
  along.normalize();
  // Towards the top of the glyphs: the image's "up" for upright text (y grows downwards),
  // flipped when the quad's own top edge says otherwise.
  Eigen::Vector2d up(along.y(), -along.x());
  const Eigen::Vector2d quad_up = 0.5 * (quad[0] + quad[1] - quad[2] - quad[3]);
  if (quad_up.dot(up) < 0.0) up = -up;
  double lo_a = 1e300, hi_a = -1e300, lo_u = 1e300, hi_u = -1e300;
  for (const auto& p : quad) {
    lo_a = std::min(lo_a, p.dot(along));
    hi_a = std::max(hi_a, p.dot(along));
    lo_u = std::min(lo_u, p.dot(up));
    hi_u = std::max(hi_u, p.dot(up));
  }
  lo_a -= margin;
  hi_a += margin;
  lo_u -= margin;
  hi_u += margin;
  return {lo_a * along + hi_u * up, hi_a * along + hi_u * up, hi_a * along + lo_u * up,
          lo_a * along + lo_u * up};
}

std::vector<ocr::RegionOfInterest> predictRegions(const geometry::RigCamera& camera,
                                                  const std::vector<const map::Landmark*>& nearby,
                                                  const FloorHeights& floors,
                                                  const geometry::Pose2& pose,
                                                  const Eigen::Matrix3d& covariance,
                                                  const RoiOptions& options) {
  std::vector<ocr::RegionOfInterest> regions;
  for (auto& candidate : predictRegionCandidates(camera, nearby, floors, pose, covariance, options))
    regions.push_back(std::move(candidate.roi));
  return regions;
}

std::vector<RegionCandidate> predictRegionCandidates(
    const geometry::RigCamera& camera, const std::vector<const map::Landmark*>& nearby,
    const FloorHeights& floors, const geometry::Pose2& pose, const Eigen::Matrix3d& covariance,
    const RoiOptions& options) {
  std::vector<RegionCandidate> regions;
  for (const map::Landmark* landmark : nearby) {
    const auto corners = floors.cornersAboveFloor(*landmark);
    const Eigen::Matrix3d pose_and_map = withMapPositionError(covariance, landmark->accuracy);
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
          p->J_pixel_pose * pose_and_map * p->J_pixel_pose.transpose();
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

    RegionCandidate candidate;
    const auto grown = readingAlignedBox(quad, grow);
    for (int i = 0; i < 4; ++i)
      candidate.roi.polygon[i] =
          cv::Point2f(static_cast<float>(grown[i].x()), static_cast<float>(grown[i].y()));
    candidate.roi.expected_texts.push_back(landmark->text);
    candidate.roi.expected_class = landmark->cls;
    for (int i = 0; i < 4; ++i)
      candidate.roi.predicted[i] =
          cv::Point2f(static_cast<float>(quad[i].x()), static_cast<float>(quad[i].y()));
    candidate.landmark_id = landmark->id;
    candidate.size_px = longest;
    const auto tight = readingAlignedBox(quad, 0.0);
    candidate.height_px = (tight[0] - tight[3]).norm();
    regions.push_back(std::move(candidate));
  }
  return regions;
}

}  // namespace parkloc::localize
