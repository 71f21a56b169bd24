#include "localize/frame_types.h"

namespace parkloc::localize {

std::string toString(TrackingStatus status) {
  switch (status) {
    case TrackingStatus::kNotInitialised:
      return "not_initialised";
    case TrackingStatus::kOk:
      return "ok";
    case TrackingStatus::kDeadReckoning:
      return "dead_reckoning";
    case TrackingStatus::kLost:
      return "lost";
  }
  return "unknown";
}

std::string toString(AssociationVerdict verdict) {
  switch (verdict) {
    case AssociationVerdict::kAccepted:
      return "accepted";
    case AssociationVerdict::kWrongClass:
      return "wrong_class";
    case AssociationVerdict::kLowScore:
      return "low_score";
    case AssociationVerdict::kNotInMap:
      return "not_in_map";
    case AssociationVerdict::kAnomaly:
      return "anomaly";
    case AssociationVerdict::kGated:
      return "gated";
    case AssociationVerdict::kFlipped:
      return "flipped";
    case AssociationVerdict::kSolverOutlier:
      return "solver_outlier";
    case AssociationVerdict::kNoGeometry:
      return "no_geometry";
    case AssociationVerdict::kAmbiguous:
      return "ambiguous";
    case AssociationVerdict::kUnconfirmed:
      return "unconfirmed";
    case AssociationVerdict::kPartial:
      return "partial";
  }
  return "unknown";
}

}  // namespace parkloc::localize
