#include "localize/association.h"

#include <cmath>
#include <limits>
#include <optional>

#include "localize/association_gate.h"
#include "localize/shared_places.h"

namespace parkloc::localize {
namespace {

std::array<Eigen::Vector2d, 4> toEigen(const std::array<cv::Point2f, 4>& polygon) {
  std::array<Eigen::Vector2d, 4> out;
  for (int i = 0; i < 4; ++i) out[i] = {polygon[i].x, polygon[i].y};
  return out;
}

// Accepted beats flipped beats gated (among the landmarks that carry one text).
int rank(AssociationVerdict v) {
  return v == AssociationVerdict::kAccepted ? 0 : v == AssociationVerdict::kFlipped ? 1 : 2;
}

}  // namespace

Associator::Associator(const geometry::Rig& rig, const map::HdMap& map, const FloorHeights& floors,
                       const AssociationOptions& options, const PaperModuleOptions& modules,
                       PolygonModel polygon_model, bool paper_mode, double surveyed_size_sigma)
    : rig_(rig),
      map_(map),
      floors_(floors),
      options_(options),
      modules_(modules),
      polygon_model_(polygon_model),
      paper_mode_(paper_mode),
      surveyed_size_sigma_(surveyed_size_sigma) {
  gate_options_.centre_sigma_px = options.gate_centre_sigma_px;
  gate_options_.min_radius_m = options.gate_min_radius_m;
  reset();
}

void Associator::reset() { afm_ = BoxPlotFilter(afmOptions(modules_)); }

AssociatedObservations Associator::associate(const std::vector<CameraResult>& cameras,
                                             const std::vector<bool>& supplied, bool tracking,
                                             const LevelEstimate& level, const PoseEkf& ekf,
                                             std::vector<Association>& associations) {
  AssociatedObservations out;
  // The box plot (paper 3.3) assumes the numbers in view change slowly; after a turn into
  // another aisle they jump and it rejects the new ones for a while. While parkloc
  // tracks, the pose gate tests every reading against where its landmark must be, so the
  // box plot filters only before the first fix (and in the paper's pipeline); the gated
  // numbers keep its queue current for when the track is lost.
  const bool afm_filters_readings = modules_.afm && (paper_mode_ || !tracking);
  for (size_t c = 0; c < cameras.size(); ++c) {
    const auto& instances = cameras[c].instances;
    const bool use_corners = polygon_model_ == PolygonModel::kCorners ||
                             (polygon_model_ == PolygonModel::kAuto && supplied[c]);
    for (size_t i = 0; i < instances.size(); ++i) {
      const auto& instance = instances[i];
      Association a;
      a.camera = cameras[c].camera;
      a.instance_index = static_cast<int>(i);
      a.text = instance.text;
      const int tag = static_cast<int>(associations.size());
      // The numeric part of a parking number, for the box plot.
      const std::optional<int> number = parkingNumberValue(instance.text);
      const bool is_number = instance.cls == map::TextClass::kParkingNumber && number.has_value();
      const bool usable_class =
          (instance.cls == map::TextClass::kParkingNumber && options_.use_parking_numbers) ||
          (instance.cls == map::TextClass::kPillar && options_.use_pillar_text && !paper_mode_);
      if (!usable_class) {
        a.verdict = AssociationVerdict::kWrongClass;
      } else if (instance.recognition_score < options_.min_recognition_score) {
        a.verdict = AssociationVerdict::kLowScore;
      } else if (afm_filters_readings && instance.read && is_number && !afm_.accept(*number)) {
        a.verdict = AssociationVerdict::kAnomaly;
      } else if (instance.partial) {
        a.verdict = AssociationVerdict::kPartial;
      } else if (instance.second_opinion && !tracking) {
        // A wrong second opinion once made a first fix 16.6 m off that the track never left
        // (docs/OCR.md): only the pose gate may vouch for one.
        a.verdict = AssociationVerdict::kUnconfirmed;
      } else {
        std::vector<const map::Landmark*> candidates =
            map_.findByText(instance.text, level.restriction());
        if (!level.belief().decided)
          candidates =
              onePerPlace(candidates, level.belief().level, level.options().shared_place_m,
                          surveyed_size_sigma_);
        const auto observe = [&](const map::Landmark& landmark) {
          LandmarkObservation o;
          o.camera = static_cast<int>(c);
          o.landmark_id = landmark.id;
          o.pixels = toEigen(instance.polygon);
          o.map_corners = floors_.cornersAboveFloor(landmark);
          o.tag = tag;
          o.use_corners = use_corners && !(options_.box_only_centre && instance.box_only);
          o.accuracy = landmark.accuracy;
          // A text the map has at several places (a level sign, a pillar's faces) is
          // associated by the predicted pose, so it cannot tell that the pose is wrong.
          o.read = instance.read && !instance.second_opinion && candidates.size() == 1;
          return o;
        };
        LandmarkObservation o;
        if (candidates.empty()) {
          a.verdict = AssociationVerdict::kNotInMap;
        } else if (tracking) {
          // Gate every landmark with this text (pillar faces, other levels): the one that
          // fits the prediction best, reading the right way round, is the association.
          AssociationVerdict best_verdict = AssociationVerdict::kGated;
          double best_m2 = std::numeric_limits<double>::infinity();
          for (const map::Landmark* l : candidates) {
            const LandmarkObservation candidate = observe(*l);
            const auto gate = gateObservation(rig_.cameras[c], candidate, ekf.pose(),
                                              ekf.covariance(), gate_options_);
            if (!gate) continue;
            const AssociationVerdict verdict =
                !gate->reading_order_agrees               ? AssociationVerdict::kFlipped
                : gate->mahalanobis2 > options_.gate_chi2 ? AssociationVerdict::kGated
                                                          : AssociationVerdict::kAccepted;
            // The better verdict; then the smaller distance.
            if (rank(verdict) < rank(best_verdict) ||
                (rank(verdict) == rank(best_verdict) && gate->mahalanobis2 < best_m2)) {
              best_verdict = verdict;
              best_m2 = gate->mahalanobis2;
              o = candidate;
            }
          }
          if (o.camera < 0) o = observe(*candidates.front());  // projects nowhere: gated
          a.verdict = best_verdict;
          a.landmark_id = o.landmark_id;
          if (std::isfinite(best_m2)) a.mahalanobis2 = best_m2;
        } else if (candidates.size() > 1 && !paper_mode_) {
          a.verdict = AssociationVerdict::kAmbiguous;
        } else {
          o = observe(*candidates.front());
          a.landmark_id = o.landmark_id;
          a.verdict = AssociationVerdict::kAccepted;
        }
        if (o.camera >= 0) {
          if (a.verdict == AssociationVerdict::kAccepted) out.accepted.push_back(o);
          // Re-localisation uses unique texts only, first opinions only: a gated pillar face
          // could be any face, and a gated second opinion is likelier a misreading.
          if (a.verdict == AssociationVerdict::kGated && candidates.size() == 1 &&
              !instance.second_opinion)
            out.gated.push_back(o);
        }
      }
      // A number the pose gate accepted keeps the box plot's queue current.
      if (!a.landmark_id.empty() && a.verdict == AssociationVerdict::kAccepted && modules_.afm &&
          !afm_filters_readings && is_number)
        afm_.remember(*number);
      associations.push_back(std::move(a));
    }
  }
  return out;
}

}  // namespace parkloc::localize
