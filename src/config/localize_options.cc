#include "config/localize_options.h"

#include "config/numbering_options.h"

namespace parkloc::config {
namespace {

void describe(OptionVisitor& v, localize::MotionOptions& o) {
  v.value("use_odometry", o.use_odometry,
          "predict with wheel odometry; false: constant velocity from the last fixes");
  v.value("odometry_gap_s", o.odometry_gap_s,
          "odometry older than this at a frame set is a dropped sensor (random walk)");
  v.value("constant_velocity_max_gap_s", o.constant_velocity_max_gap_s,
          "fixes further apart than this give no velocity (the vehicle may have turned)");
  v.value("use_capture_times", o.use_capture_times,
          "use each camera image at its own capture time; false: at the frame set's time");
}

void describe(OptionVisitor& v, localize::EkfOptions& o) {
  v.value("speed_sigma", o.speed_sigma, "odometry speed noise, m/s (1 sigma)");
  v.value("yaw_rate_sigma", o.yaw_rate_sigma, "odometry yaw-rate white noise, rad/s");
  v.value("yaw_rate_bias_sigma", o.yaw_rate_bias_sigma,
          "prior of the gyro's yaw-rate bias, a filter state, rad/s");
  v.value("yaw_rate_bias_walk", o.yaw_rate_bias_walk,
          "random walk of that bias, rad/s/sqrt(s): it drifts with temperature");
  v.value("odometry_learning_delay_s", o.odometry_learning_delay_s,
          "fixes teach the bias and scale only this long after the filter starts (0: at once)");
  v.value("speed_scale_sigma", o.speed_scale_sigma,
          "prior of the speed scale (wheel radius error) around 1, a filter state");
  v.value("speed_scale_walk", o.speed_scale_walk, "random walk of the speed scale, 1/sqrt(s)");
  v.value("no_odometry_position_sigma", o.no_odometry_position_sigma,
          "position random walk without odometry, m/sqrt(s)");
  v.value("no_odometry_yaw_sigma", o.no_odometry_yaw_sigma,
          "yaw random walk without odometry, rad/sqrt(s)");
  v.value("map_error_landmarks", o.map_error_landmarks,
          "landmarks whose map error (a survey error every fix of them repeats) are filter "
          "states; 0: none, the map_reuse_cap and map_covariance_floor rules instead");
}

void describe(OptionVisitor& v, localize::ReadingOptions& o) {
  v.value("map_guided", o.map_guided,
          "while tracking, spot only where the map predicts text; false: full frames always");
  v.value("full_frame_interval", o.full_frame_interval,
          "while tracking, each camera gets a full-frame sweep once per this many frame sets");
  v.value("full_frame_round_robin", o.full_frame_round_robin,
          "sweep one camera at a time, so no frame set spots two full frames (p99 latency)");
  v.value("search_cameras_per_frame", o.search_cameras_per_frame,
          "before the first fix, cameras spotted on the full frame per frame set (0: all)");
  v.value("search_max_reads", o.search_max_reads,
          "before the first fix, texts read per camera, the largest (nearest) first (0: all)");
  v.value("search_detection_scale", o.search_detection_scale,
          "before the first fix, the detector's input scale: the turn comes back soon");
  v.value("roi_radius_m", o.roi_radius_m,
          "map texts within this radius of the predicted pose are projected into the cameras");
  v.value("roi_margin_px", o.roi_margin_px,
          "a predicted region grows by the pose uncertainty and this margin (survey, jitter)");
  v.value("roi_min_size_px", o.roi_min_size_px, "predicted text smaller than this is unreadable");
  v.value("roi_min_height_px", o.roi_min_height_px,
          "predicted text flatter than this (a grazing view) is skipped by the region budget");
  v.value("max_regions_per_frame", o.max_regions_per_frame,
          "regions per frame set, the most useful first (<= 0: all; a budget of 3 lost turns)");
  v.value("max_regions_with_full_frame", o.max_regions_with_full_frame,
          "region budget of the other cameras on a frame set that sweeps one");
  v.value("reread_interval_frames", o.reread_interval_frames,
          "a landmark read within this many frame sets is only fitted to its ink, not read");
  v.value("max_reads_per_frame", o.max_reads_per_frame,
          "regions read per frame set, the largest unread first (<= 0: no limit)");
  v.value("level_place_reads", o.level_place_reads,
          "while the level is undecided, reads that go first to places whose text differs between "
          "levels (0: by size alone)");
  v.value("tracked_min_height_px", o.tracked_min_height_px,
          "predicted text flatter than this is not fitted: its corners would not fix the pose");
  v.value("tentative_reads_whole_lexicon", o.tentative_reads_whole_lexicon,
          "a tentative track reads regions against every map text, not the predicted one");
  v.value("tentative_full_frame_interval", o.tentative_full_frame_interval,
          "a tentative track sweeps each camera once per this many frame sets (<= 1: as tracking)");
  v.value("sweep_detection_scale", o.sweep_detection_scale,
          "the tracking sweep's detector input scale: it only catches what the prediction missed");
  v.value("sweep_places_floor_texts", o.sweep_places_floor_texts,
          "the sweep reads a floor box only the way round the texts placed near it read");
  v.value("sweep_placement_range_m", o.sweep_placement_range_m,
          "floor texts placed out to this range: the floor views' reach");
  v.value("sweep_placement_radius_m", o.sweep_placement_radius_m,
          "placed texts looked for within this radius of a box");
  v.value("second_opinions", o.second_opinions,
          "ask the second recognizer on full frames (costs 30-50 ms at p99, moved no error)");
  v.value("numbering_competitors", o.numbering_competitors,
          "with a map not complete, full frames also read the numbers of its formats it lacks");
  v.section("numbering", "how the map's numbering formats are learnt from its numbers",
            [&] { describe(v, o.numbering); });
}

void describe(OptionVisitor& v, localize::LevelOptions& o) {
  v.value("decided_probability", o.decided_probability, "a level this probable is decided");
  v.value("sign_ratio", o.sign_ratio,
          "likelihood ratio of one reading of a level sign (\"B2\") for its level");
  v.value("text_ratio", o.text_ratio,
          "likelihood ratio of one reading of a text for the levels that have it");
  v.value("place_ratio", o.place_ratio,
          "likelihood ratio of a gated text for the levels that have it at that place");
  v.value("max_frame_ratio", o.max_frame_ratio,
          "no frame set moves the odds between two levels by more than this");
  v.value("ramp_after_s", o.ramp_after_s,
          "a stretch with no text associated for this long (s) may be a ramp");
  v.value("change_rate_per_s", o.change_rate_per_s,
          "level changes per second on such a stretch");
  v.value("min_probability", o.min_probability,
          "no level's probability falls below this (readings are not independent)");
  v.value("hint_probability", o.hint_probability, "the probability a level hint starts with");
  v.value("shared_place_m", o.shared_place_m,
          "landmarks of two levels this close (same surface and direction) are one place");
  v.value("min_recognition_score", o.min_recognition_score,
          "readings with a lower score say nothing of the level");
}

void describe(OptionVisitor& v, localize::AssociationOptions& o) {
  v.value("use_parking_numbers", o.use_parking_numbers, "parking numbers may fix the pose");
  v.value("use_pillar_text", o.use_pillar_text, "pillar texts may fix the pose");
  v.value("min_recognition_score", o.min_recognition_score,
          "readings with a lower score are not used");
  v.value("gate_chi2", o.gate_chi2,
          "pose gate on a landmark centre, squared Mahalanobis, 2 dof (13.8: 99.9 %)");
  v.value("gate_min_radius_m", o.gate_min_radius_m,
          "the gate never assumes less position uncertainty than this (map survey error)");
  v.value("gate_centre_sigma_px", o.gate_centre_sigma_px,
          "pixel noise of an observed text centre on top of the pose uncertainty");
  v.value("box_only_centre", o.box_only_centre,
          "a text whose corners found no ink fit (the detector's box) measures its centre only");
}

void describe(OptionVisitor& v, localize::PaperModuleOptions& o) {
  v.value("afm", o.afm, "the box-plot anomaly filter on parking numbers (paper section 3.3)");
  v.value("mcrp", o.mcrp, "average one landmark over the cameras that see it (section 3.5)");
  v.value("mcap", o.mcap, "use every landmark seen, not only the largest (section 3.5)");
  v.value("afm_queue_length", o.afm_queue_length, "the AFM's queue of recent numbers (paper: 30)");
  v.value("afm_iqr_factor", o.afm_iqr_factor, "the AFM's box: median +- k IQR (paper: 1.5)");
  v.value("afm_reset_after_rejections", o.afm_reset_after_rejections,
          "refill the AFM's queue after this many rejections in a row, for a new aisle (0: never)");
}

void describe(OptionVisitor& v, localize::SolverOptions& o) {
  v.value("pixel_sigma", o.pixel_sigma, "corner noise (1 sigma, pixels) for the covariance");
  v.value("huber_threshold_px", o.huber_threshold_px,
          "Huber threshold on a corner's pixel error: a misplaced corner weighs less");
  v.value("max_iterations", o.max_iterations, "Gauss-Newton iterations at most");
  v.value("step_tolerance", o.step_tolerance, "converged when |dx| + |dy| + |dyaw| falls below");
  v.value("inlier_threshold_px", o.inlier_threshold_px,
          "an observation is an inlier when its mean corner error is below this");
  v.value("centre_fallback_px", o.centre_fallback_px,
          "an outlier whose centre lies this near its prediction keeps its centre (0: off)");
  v.value("max_hypotheses", o.max_hypotheses, "single-text hypotheses tried, the largest texts");
  v.value("assumed_map_position_sigma_m", o.assumed_map_position_sigma_m,
          "a landmark's position error (1 sigma per axis, m) where the map states none (0: exact)");
  v.value("assumed_map_heading_sigma_deg", o.assumed_map_heading_sigma_deg,
          "a landmark's heading error (1 sigma, degrees) where the map states none (0: exact)");
  v.value("map_size_sigma", o.map_size_sigma,
          "a map stating its accuracy gives nominal painted sizes: relative error, 1 sigma");
  v.value("assumed_map_size_sigma", o.assumed_map_size_sigma,
          "a map stating no accuracy: relative size error (0: exact ink boxes)");
}

void describe(OptionVisitor& v, localize::MeasurementOptions& o) {
  v.choice("polygon_model", o.polygon_model,
           {{"auto", localize::PolygonModel::kAuto},
            {"corners", localize::PolygonModel::kCorners},
            {"centre", localize::PolygonModel::kCentre}},
           "what a text's polygon measures in the solver");
  v.value("fix_covariance_inflation", o.fix_covariance_inflation,
          "OCR corner errors are correlated: the filter sees the fix covariance this much wider");
  v.value("map_covariance_floor", o.map_covariance_floor,
          "the filter keeps at least this times a fix's map-error covariance (0: off)");
}

void describe(OptionVisitor& v, localize::TrackingOptions& o) {
  v.value("lost_position_sigma_m", o.lost_position_sigma_m,
          "the track is lost beyond this 1-sigma position uncertainty");
  v.value("first_fix_max_sigma_m", o.first_fix_max_sigma_m,
          "a first fix starts the track only within this 1-sigma position (0: any fix)");
  v.value("fix_gate_chi2", o.fix_gate_chi2,
          "a fix is fused within this squared Mahalanobis distance, 3 dof (16.3: 99.9 %)");
  v.value("reinit_after_rejected_fixes", o.reinit_after_rejected_fixes,
          "consistent fixes outside the gate that re-initialise the track (a kidnap)");
  v.value("confirm_read_landmarks", o.confirm_read_landmarks,
          "a track is tentative until this many distinct landmarks were read with it (fits: no)");
  v.value("tentative_reinit_after_rejected_fixes", o.tentative_reinit_after_rejected_fixes,
          "consistent fixes from reads that re-initialise a tentative track (x2 on one landmark)");
  v.value("reinit_consistency_m", o.reinit_consistency_m,
          "two gated-out fixes agree within this distance, carried by the motion");
  v.value("reinit_consistency_deg", o.reinit_consistency_deg, "... and this heading");
  v.value("initial_position_sigma_m", o.initial_position_sigma_m,
          "uncertainty of a given initial pose (1 sigma)");
  v.value("initial_yaw_sigma_deg", o.initial_yaw_sigma_deg, "... its heading");
  v.value("map_reuse_cap", o.map_reuse_cap,
          "a landmark's map error informs the filter about once: its n-th fusion weighs 1/n");
}

void describe(OptionVisitor& v, localize::PaperPipelineOptions& o) {
  v.choice("heading", o.heading,
           {{"text_direction", localize::PaperHeadingSource::kTextDirection},
            {"motion_direction", localize::PaperHeadingSource::kMotionDirection},
            {"odometry", localize::PaperHeadingSource::kOdometry}},
           "where the paper's pipeline, which estimates no heading, gets one");
  v.value("centre_from_polygon", o.centre_from_polygon,
          "text centre: mean of the polygon corners; false: the axis-aligned box's (paper)");
  v.value("heading_min_travel_m", o.heading_min_travel_m,
          "motion_direction: heading from travel once the vehicle has moved this far");
}

void describe(OptionVisitor& v, localize::RealtimeOptions& o) {
  v.value("background_search", o.background_search,
          "full-frame spotting on a worker thread, fused at its capture time when ready; "
          "false: the frame set that carries it waits");
  v.value("wait_for_worker", o.wait_for_worker,
          "fuse the worker's texts exactly fuse_after_frames later, waiting for it "
          "(reproducible); false: when ready (parkloc run --realtime)");
  v.value("fuse_after_frames", o.fuse_after_frames,
          "wait_for_worker: frame sets between the images and the fusion of their texts");
  v.value("worker_nice", o.worker_nice,
          "the worker thread's nice value: the critical path wins the cores");
  v.value("worker_inference_threads", o.worker_inference_threads,
          "inference threads of the worker's own spotter (1: all on the worker thread)");
  v.value("background_reads", o.background_reads,
          "the reads at predicted places on a worker of their own, fused at their capture "
          "time; the frame set keeps the ink fits of texts read lately");
  v.value("warm_up", o.warm_up,
          "every spotter reads a made-up full frame of each camera at start (the first "
          "inference costs 2-3 times a later one)");
  v.value("first_fix_wait_ms", o.first_fix_wait_ms,
          "live, before the first fix: how long a frame set waits for a full frame in a "
          "worker's hands (0: no wait)");
}

}  // namespace

void describe(OptionVisitor& v, localize::PipelineOptions& o) {
  v.value("paper_mode", o.paper_mode,
          "run the paper's pipeline instead of parkloc's (the CLI's --paper sets the rest)");
  v.value("level", o.level,
          "a hint: the map level the drive starts on (\"\": estimated from the texts seen)");
  v.section("levels", "the level estimate", [&] { describe(v, o.levels); });
  v.section("motion", "odometry intake and prediction", [&] { describe(v, o.motion); });
  v.section("ekf", "the filter's noise model", [&] { describe(v, o.ekf); });
  v.section("reading", "what to read each frame set", [&] { describe(v, o.reading); });
  v.section("association", "texts to map landmarks", [&] { describe(v, o.association); });
  v.section("paper_modules", "the paper's AFM / MCRP / MCAP switches",
            [&] { describe(v, o.paper_modules); });
  v.section("solver", "the SE(2) robust least squares on text corners",
            [&] { describe(v, o.solver); });
  v.section("measurement", "what a fix measures", [&] { describe(v, o.measurement); });
  v.section("tracking", "the track's lifecycle: first fix, loss, re-localisation",
            [&] { describe(v, o.tracking); });
  v.section("paper_pipeline", "the paper's positioning", [&] { describe(v, o.paper_pipeline); });
  v.section("realtime", "full-frame spotting off the frame set's critical path",
            [&] { describe(v, o.realtime); });
}

}  // namespace parkloc::config
