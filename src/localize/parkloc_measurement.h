#pragma once
// Stage 5 of parkloc's pipeline, the measurement: the vehicle's SE(2) pose from every corner
// of every accepted text (pose_solver.h), and its covariance as the filter sees it. While
// tracking, the solve starts from the prediction and a fix outside the filter's gate is set
// aside for re-localisation, as is a consistent other place that the gated texts alone
// describe. While searching, this frame set's texts are solved with those of the search
// window. The fixes then go to the track's lifecycle (track_lifecycle.h).
#include <vector>

#include "geometry/rig.h"
#include "localize/frame_types.h"
#include "localize/landmark_observation.h"
#include "localize/pose_ekf.h"
#include "localize/pose_solver.h"
#include "localize/search_window.h"
#include "localize/track_lifecycle.h"

namespace parkloc::localize {

struct MeasurementOptions {
  // What a text's polygon measures in the solver (landmark_observation.h). Corners measured
  // better on real OCR with the solver's outlier rejection than centres (2.1 against 4.2 cm
  // mean error on a simulated drive).
  PolygonModel polygon_model = PolygonModel::kCorners;
  // The solver's covariance assumes independent corner noise; OCR polygon errors are
  // correlated over corners and frames, so the filter sees it inflated by this factor (and by
  // (rms / pixel_sigma)^2 when the corners fit worse than pixel_sigma). Chosen on the
  // validation drives: the NEES inside its 95 % bound on 69 / 97 / 95 % of their frames.
  double fix_covariance_inflation = 8.0;
  // The map's share of a fix's covariance (SolverResult::map_covariance) is the same error in
  // every frame that sees the same landmarks, so fusing frame after frame cannot shrink it:
  // a fusion does not take the filter's pose covariance below the smaller of what it was and
  // this times that share (PoseEkf::update). 0: off.
  double map_covariance_floor = 2.0;
};

// A fix's covariance as the filter sees it: its pixel-noise part (covariance less
// map_covariance) inflated, grown by how much worse than the assumed pixel noise the corners
// fit (a-posteriori variance factor: a fix from one text seen
// at a grazing angle whose corners fit to 6 px must not count as one that fits to 1), with a
// floor of 1 cm and 0.05 degrees, so that no fix, however many exact corners it rests on,
// tells the filter it is exact. The map's part is added as it is: it comes from the map's
// stated sigmas, not from the corners' fit.
Eigen::Matrix3d fixCovariance(const SolverResult& fix, double pixel_sigma,
                              const MeasurementOptions& options);

// The same for a filter that keeps the map errors as states: the solve's pixel-noise part
// (SolverResult::pixel_covariance), inflated as above, with the same floor; the map's part
// enters through SolverResult::map_terms.
Eigen::Matrix3d fixPixelCovariance(const SolverResult& fix, double pixel_sigma,
                                   const MeasurementOptions& options);

class ParklocMeasurement {
 public:
  // The rig must outlive the measurement.
  ParklocMeasurement(const geometry::Rig& rig, const SolverOptions& solver,
                     const MeasurementOptions& options, const TrackingOptions& tracking)
      : rig_(rig), solver_(solver), options_(options), tracking_(tracking) {}

  // While tracking: the solve from the prediction on the accepted texts; when it gives no
  // fix within the gate, the solve on the gated texts too (a consistent other place?). On a
  // `tentative` track (track_lifecycle.h) the texts read this frame set, when some were
  // gated away, are solved on their own as well, even when the fix agrees: the fits that
  // agree with a wrong pose read nothing.
  FrameFixes whileTracking(const std::vector<LandmarkObservation>& accepted,
                           const std::vector<LandmarkObservation>& gated, const PoseEkf& ekf,
                           bool tentative, FrameResult& result) const;

  // While searching: the accepted texts with those of the search window. A certain fix
  // empties the window; otherwise this frame set's texts join it.
  FrameFixes whileSearching(const std::vector<LandmarkObservation>& accepted, SearchWindow& window,
                            FrameResult& result) const;

 private:
  PoseFix toFix(const SolverResult& solve, const std::vector<LandmarkObservation>& obs) const;

  const geometry::Rig& rig_;
  SolverOptions solver_;
  MeasurementOptions options_;
  TrackingOptions tracking_;
};

}  // namespace parkloc::localize
