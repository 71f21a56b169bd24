#include "ocr/placed_classes.h"

namespace parkloc::ocr {

ClassWeights floorClassWeightsNear(const std::vector<map::PlacedText>& placed,
                                   const Eigen::Vector2d& vehicle_xy, double radius,
                                   float unplaced_other) {
  ClassWeights weights = {0.f, 0.f, unplaced_other};
  bool any = false;
  for (const map::PlacedText& p : placed) {
    if ((p.vehicle_xy - vehicle_xy).norm() > radius || p.cls == map::TextClass::kPillar) continue;
    weights[static_cast<size_t>(p.cls)] = 1.f;
    any = true;
  }
  if (!any) weights[static_cast<size_t>(map::TextClass::kOther)] = 1.f;
  return weights;
}

}  // namespace parkloc::ocr
