#pragma once
// The per-frame localization pipeline: text instances from the four cameras -> the
// vehicle's pose in the garage, every frame set. Its stages, in the order data flows:
//
//   1. motion prediction   odometry in, the EKF predicted to the frame set (motion_prediction.h)
//   2. read planning       full frame or map-guided regions, reads or fits (read_planning.h)
//   3. spotting            the injected ocr::TextSpotter, camera by camera (spotting.h)
//   4. level and association   the level estimate (level_estimate.h); exact matching, AFM box plot,
//                          pose gate, reading order (association.h); MCRP / MCAP (paper_modules.h)
//   (background) full frames go to the search worker (search_worker.h) and their texts
//                          come back to stage 4 a frame set or more later, fused at their
//                          capture time (late_fusion.h)
//   5. measurement         parkloc: SE(2) robust least squares on every polygon corner
//                          (parkloc_measurement.h), then the track's lifecycle: EKF update,
//                          first fix, loss, re-localisation (track_lifecycle.h);
//                          the paper: centre homography + MCRP / MCAP averaging (paper_pipeline.h)
//
// The spotter is injected (ocr::TextSpotter), so this module knows nothing of ONNX. An
// oracle source (ground-truth labels, run/oracle_source.h) passes instances in FrameInput
// instead of images.
#include <memory>
#include <optional>
#include <string>

#include "geometry/pose.h"
#include "geometry/rig.h"
#include "localize/association.h"
#include "localize/frame_types.h"
#include "localize/level_estimate.h"
#include "localize/motion_prediction.h"
#include "localize/paper_modules.h"
#include "localize/paper_pipeline.h"
#include "localize/parkloc_measurement.h"
#include "localize/pose_ekf.h"
#include "localize/pose_solver.h"
#include "localize/read_planning.h"
#include "localize/search_worker.h"
#include "localize/track_lifecycle.h"
#include "map/hd_map.h"
#include "ocr/text_spotter.h"

namespace parkloc::localize {

// Every option of the pipeline, one section per stage.
struct PipelineOptions {
  // Run the paper's pipeline (OCR-RTPS section 3, paper_pipeline.h) instead of parkloc's.
  // paper() sets the rest of what the paper does; the paper_modules switches still apply.
  bool paper_mode = false;
  // A hint: the map level the drive starts on (e.g. the car entered on B1); "": none, the
  // level is estimated from the texts seen (level_estimate.h).
  std::string level;
  // A known starting pose (e.g. where the vehicle was parked); otherwise the first certain
  // fix starts the track.
  std::optional<geometry::Pose2> initial_pose;

  LevelOptions levels;                  // the level estimate (level_estimate.h)
  MotionOptions motion;                 // odometry intake (motion_prediction.h)
  EkfOptions ekf;                       // the filter's noise model (pose_ekf.h)
  ReadingOptions reading;               // what to read each frame set (read_planning.h)
  AssociationOptions association;       // texts to landmarks (association.h)
  PaperModuleOptions paper_modules;     // AFM / MCRP / MCAP (paper_modules.h)
  SolverOptions solver;                 // the SE(2) solve (pose_solver.h)
  MeasurementOptions measurement;       // what a fix measures (parkloc_measurement.h)
  TrackingOptions tracking;             // the track's lifecycle (track_lifecycle.h)
  PaperPipelineOptions paper_pipeline;  // the paper's positioning (paper_pipeline.h)
  RealtimeOptions realtime;             // full frames off the critical path (search_worker.h)

  // The paper's pipeline on `base`'s other options: paper_mode on, no odometry, full-frame
  // spotting every frame set, parking numbers only.
  static PipelineOptions paper(PipelineOptions base);
  static PipelineOptions paper() { return paper(PipelineOptions{}); }
};

class Pipeline {
 public:
  // `spotter` may be null when every frame brings its instances (oracle); a frame that
  // needs spotting without a spotter gets a warning and no instances. The rig and map
  // are copied; the spotters must outlive the pipeline. `workers.search` spots the full
  // frames on the search worker (options.realtime.background_search; null: `spotter`, shared
  // behind a mutex, serialized_spotter.h); `workers.reads` the reads at predicted places
  // (options.realtime.background_reads; null: they stay in the frame set).
  Pipeline(geometry::Rig rig, map::HdMap map, PipelineOptions options = {},
           ocr::TextSpotter* spotter = nullptr, WorkerSpotters workers = {});
  ~Pipeline();
  Pipeline(Pipeline&&) noexcept;
  Pipeline& operator=(Pipeline&&) noexcept;
  Pipeline(const Pipeline&) = delete;
  Pipeline& operator=(const Pipeline&) = delete;

  // Processes one frame set. Frames must come in increasing time; a frame not after the
  // previous one is processed without prediction and reported in warnings.
  FrameResult process(const FrameInput& frame);

  // Forgets the track and the AFM queue (a new drive); waits for the search worker's job in
  // hand and drops it.
  void reset();

  const PipelineOptions& options() const;
  const geometry::Rig& rig() const;
  const map::HdMap& map() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace parkloc::localize
