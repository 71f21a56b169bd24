#pragma once
// `parkloc map build`, the stages in the order data flows: reading every frame set of every
// drive (sightings.h), dead reckoning (survey_poses.h), casting and the consensus reading
// (consensus.h), the landmarks' first guess (landmark_seed.h), the joint estimation of poses
// and landmarks (map_problem.h) and their uncertainty. Later drives join the first one's frame
// by the texts they share.
#include <functional>
#include <string>
#include <vector>

#include "io/sequence.h"
#include "mapping/consensus.h"
#include "mapping/landmark_estimate.h"
#include "mapping/map_problem.h"
#include "mapping/sightings.h"
#include "mapping/stencil_height.h"
#include "mapping/survey_poses.h"
#include "ocr/text_spotter.h"

namespace parkloc::mapping {

struct MapBuildOptions {
  ReadingOptions reading;
  ConsensusOptions consensus;
  EstimationOptions estimation;
  // The estimated distance over the odometry's: beyond this relative difference the odometry
  // disagrees with what the cameras see (a wrong wheel radius), and the build says so.
  double odometry_scale_tolerance = 0.03;
  // A landmark whose corners reproject worse than this after the estimation, in the median or
  // the RMS (pixels), is no flat text on the floor where the sightings say: a pillar's text
  // read as a floor box is off by its height in every view (the median), a box that took in a
  // pillar's text and the floor (`2X2`, 47 px RMS on a train drive) fits now one, now the
  // other (the RMS). It is left out and the rest estimated again. A true landmark's sightings
  // include boxes the detector cut or merged, which the robust loss discounts but the RMS
  // does not: on the train and validation drives true landmarks reach 12.4 px RMS, their
  // medians at most 3.3 px (71 landmarks).
  double max_median_px = 6.0;
  double max_rms_px = 20.0;
  // Heights too far off their class's stencil height take it (stencil_height.h).
  StencilOptions stencil;
};

struct DriveOutcome {
  std::string dir;
  ReadingStats reading;
  size_t sightings = 0;
  std::vector<geometry::Pose2> dead_reckoned;  // in the map frame (before the estimation)
  std::vector<geometry::Pose2> estimated;
  double odometry_distance_m = 0.0;
  double estimated_distance_m = 0.0;
  // The odometry's calibration the estimation found (odometry_factor.h): true distance over
  // measured, less 1, and the gyro's yaw-rate bias (rad/s).
  double distance_scale = 0.0;
  double yaw_rate_bias = 0.0;
  // The corner margins it found (pixels; corner_factor.h): ink fits, boxes without a fit.
  double fitted_margin_px = 0.0;
  double unfitted_margin_px = 0.0;
};

struct MapBuild {
  std::vector<LandmarkEstimate> landmarks;
  std::vector<Sighting> sightings;  // everything read, of every drive
  std::vector<DriveOutcome> drives;
  Consensus consensus;  // counts and duplicates; its tracks are the landmarks' sightings
  std::vector<std::string> inconsistent;  // left out by MapBuildOptions::max_median_px, max_rms_px
  std::vector<std::string> stencil_heights;  // heights set by MapBuildOptions::stencil
  EstimationSummary estimation;
  bool has_uncertainty = false;
  // The numbering formats the drives were read against (given, then learnt).
  std::vector<map::NumberingFormat> numbering;
  // What the build could not do or doubts, one line each (empty: nothing).
  std::vector<std::string> problems;
};

// Throws InputError when a drive has no odometry, when a later drive shares fewer than two
// texts with the earlier ones, or when no text makes a landmark. `progress` (may be empty)
// is told (drive, frame sets done, total). `read_before`: the drives' sightings as an
// earlier build read them (sightings_json.h), instead of reading with `spotter`.
MapBuild buildMap(const std::vector<const io::Sequence*>& drives, ocr::TextSpotter* spotter,
                  const MapBuildOptions& options,
                  const std::function<void(size_t, size_t, size_t)>& progress = {},
                  const std::vector<Sighting>* read_before = nullptr);

// The estimation alone, from sightings already read and the drives' dead-reckoned poses
// (all in one frame): what buildMap does after reading. Throws InputError when no text
// makes a landmark.
MapBuild estimateMap(const std::vector<const geometry::Rig*>& rigs,
                     const std::vector<SurveyPoses>& poses, const std::vector<Sighting>& sightings,
                     const MapBuildOptions& options);

}  // namespace parkloc::mapping
