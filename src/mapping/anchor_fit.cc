#include "mapping/anchor_fit.h"

#include <fmt/format.h>

#include "common/error.h"

namespace parkloc::mapping {

AnchorFit fitAnchors(const std::vector<LandmarkEstimate>& landmarks,
                     const std::vector<io::Anchor>& anchors, bool with_scale) {
  AnchorFit out;
  std::vector<Eigen::Vector2d> from, to;
  for (const io::Anchor& a : anchors) {
    const LandmarkEstimate* match = nullptr;
    for (const LandmarkEstimate& l : landmarks)
      if (l.text == a.text) match = &l;
    if (!match) {
      out.unmatched.push_back(a.text);
      continue;
    }
    from.emplace_back(match->parameters[kX], match->parameters[kY]);
    to.push_back(a.position);
    out.used.push_back(a.text);
  }
  const auto fit = geometry::fitPlanar(from, to, with_scale);
  if (!fit)
    throw InputError(fmt::format(
        "anchors: {} of {} match a landmark of the built map, 2 at distinct places are needed",
        from.size(), anchors.size()));
  out.fit = *fit;
  return out;
}

void applyFit(const geometry::PlanarFit& fit, LandmarkEstimate& l) {
  const Eigen::Vector2d p = fit.apply({l.parameters[kX], l.parameters[kY]});
  l.parameters[kX] = p.x();
  l.parameters[kY] = p.y();
  l.parameters[kHeading] = geometry::wrapAngle(l.parameters[kHeading] + fit.to_from_from.yaw);
  l.parameters[kWidth] *= fit.scale;
  l.parameters[kHeight] *= fit.scale;
  if (l.position_sigma) *l.position_sigma *= fit.scale;
}

geometry::Pose2 applyFit(const geometry::PlanarFit& fit, const geometry::Pose2& pose) {
  const Eigen::Vector2d p = fit.apply(pose.translation());
  return {p.x(), p.y(), pose.yaw + fit.to_from_from.yaw};
}

}  // namespace parkloc::mapping
