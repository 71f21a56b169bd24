#pragma once
// Stage 4b of the pipeline, association: each text instance to a map landmark, or the
// reason it is not used (AssociationVerdict). In order: the text class, the recognition
// score, the AFM box plot (paper section 3.3), partial and unconfirmed readings, exact
// matching against the map's texts on the level driven on (section 3.3; every level while the
// level is undecided, a place the levels share counting once: shared_places.h), and, while
// tracking, the pose gate (association_gate.h): of the landmarks that carry the text (pillar
// faces, levels), the one that fits the prediction best, reading the right way round.
#include <string>
#include <vector>

#include "geometry/rig.h"
#include "localize/association_gate.h"
#include "localize/box_plot_filter.h"
#include "localize/floor_heights.h"
#include "localize/frame_types.h"
#include "localize/landmark_observation.h"
#include "localize/level_estimate.h"
#include "localize/paper_modules.h"
#include "localize/pose_ekf.h"
#include "map/hd_map.h"

namespace parkloc::localize {

struct AssociationOptions {
  // Parking numbers may be associated with the map.
  bool use_parking_numbers = true;
  // Pillar texts may be associated with the map (never in the paper's pipeline, which reads
  // parking numbers only).
  bool use_pillar_text = true;
  // Instances recognised with a lower score are not used.
  double min_recognition_score = 0.0;
  // The pose gate: a landmark centre further than this squared Mahalanobis distance (2 dof)
  // from where the prediction puts it is not associated. 13.8: 99.9 %.
  double gate_chi2 = 13.8;
  // The gate never assumes a position uncertainty below this (metres, 3 sigma): a filter
  // that has fused many fixes must still accept the survey error of the map.
  double gate_min_radius_m = 0.5;
  // Pixel noise of an observed text centre on top of the pose uncertainty (OCR polygon
  // jitter, map survey error).
  double gate_centre_sigma_px = 6.0;
  // A text whose corners are the detector's box, not fitted to its ink (ocr::TextInstance::
  // box_only), measures its centre only: the box's size follows the detector's kernel, which
  // spreads with the floor's look, and a box too small or too large for the map's text reads
  // as a text nearer or farther away.
  bool box_only_centre = false;
};

// The observations association hands to the measurement.
struct AssociatedObservations {
  std::vector<LandmarkObservation> accepted;
  // Gated away, of texts unique in the map and first opinions only: far from the prediction,
  // they tell re-localisation whether the vehicle is somewhere else (a kidnap).
  std::vector<LandmarkObservation> gated;
};

class Associator {
 public:
  // The rig, map and floors must outlive the associator. `surveyed_size_sigma`: how well a map
  // that states its accuracy knows the texts' sizes (SolverOptions::map_size_sigma).
  Associator(const geometry::Rig& rig, const map::HdMap& map, const FloorHeights& floors,
             const AssociationOptions& options, const PaperModuleOptions& modules,
             PolygonModel polygon_model, bool paper_mode, double surveyed_size_sigma);
  void reset();

  // Appends one Association per instance (cameras in order, then instances) to
  // `associations`. `supplied[c]`: camera c's instances came with the frame; `tracking`: the
  // filter's pose gates the associations.
  AssociatedObservations associate(const std::vector<CameraResult>& cameras,
                                   const std::vector<bool>& supplied, bool tracking,
                                   const LevelEstimate& level, const PoseEkf& ekf,
                                   std::vector<Association>& associations);

 private:
  const geometry::Rig& rig_;
  const map::HdMap& map_;
  const FloorHeights& floors_;
  AssociationOptions options_;
  PaperModuleOptions modules_;
  PolygonModel polygon_model_;
  bool paper_mode_;
  double surveyed_size_sigma_;
  GateOptions gate_options_;
  BoxPlotFilter afm_;
};

}  // namespace parkloc::localize
