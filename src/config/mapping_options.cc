#include "config/mapping_options.h"

#include "config/numbering_options.h"

namespace parkloc::config {
namespace {

void describe(OptionVisitor& v, mapping::ReadingOptions& o) {
  v.value("frame_step", o.frame_step, "read every this many frame sets (1: all)");
  v.value("min_recognition_score", o.min_recognition_score,
          "a less probable reading is no sighting: it would only be outvoted");
  v.value("learn_numbering", o.learn_numbering,
          "learn the numbering formats from a first free reading, then read against them");
  v.value("survey_step", o.survey_step, "the first reading reads every this many frame sets");
  v.section("numbering", "how formats are learnt from the numbers agreed on",
            [&] { describe(v, o.numbering); });
  v.value("formats", o.formats,
          "numbering formats the user knows, comma-separated, '#' a digit (e.g. C###,K2-###)");
}

void describe(OptionVisitor& v, mapping::RowSequenceOptions& o) {
  v.value("max_segment_m", o.max_segment_m,
          "two landmarks of consecutive numbers this close make a row segment");
  v.value("min_pitch_m", o.min_pitch_m, "the narrowest bay along a row, m");
  v.value("max_pitch_m", o.max_pitch_m, "the widest bay along a row, a pillar beside it, m");
  v.value("place_error_m", o.place_error_m,
          "how far a place may lie from where its sightings put it, along the row, m");
  v.value("lateral_m", o.lateral_m, "a place this close to a segment's line is on its row");
  v.value("reach_m", o.reach_m, "a segment judges places no farther along its row than this");
}

void describe(OptionVisitor& v, mapping::ConsensusOptions& o) {
  v.value("place_radius_m", o.place_radius_m,
          "sightings cast within this of a place are at it (under the 2.3 m number spacing)");
  v.value("max_range_m", o.max_range_m,
          "sightings cast from further are left out: the cast's error grows with range");
  v.value("min_frame_sets", o.min_frame_sets,
          "a landmark's reading was seen in at least this many frame sets");
  v.value("min_agreement", o.min_agreement,
          "... and in this share of the frame sets that read anything at its place ...");
  v.value("min_margin", o.min_margin,
          "... and in this many times the runner-up reading's frame sets (else ambiguous)");
  v.value("loop_radius_m", o.loop_radius_m,
          "two places of one reading this close are one text seen again (a loop) ...");
  v.value("min_frame_sets_seen_apart", o.min_frame_sets_seen_apart,
          "... unless both were read in this many of the same frame sets: two texts, one "
          "misread (0: off)");
  v.value("min_confirmed_frame_sets", o.min_confirmed_frame_sets,
          "a landmark's reading read by the first recognizer, as a number of the numbering "
          "when there is one, in at least this many frame sets (0: every reading confirms)");
  v.value("sequence_radius_m", o.sequence_radius_m,
          "of two landmarks this close whose numbers are not consecutive, the less seen is left "
          "out (0: off)");
  v.value("sequence_decides_contests", o.sequence_decides_contests,
          "a place of competing readings takes its most seen one when that one, and no rival, "
          "is consecutive to a landmark within sequence_radius_m and it is no landmark "
          "elsewhere");
  v.value("sequence_decides_for_any_reading", o.sequence_decides_for_any_reading,
          "... and the reading it takes may be any of the place's readings seen in "
          "min_frame_sets, not only the most seen one (false: the most seen only)");
  v.value("row_sequence", o.row_sequence,
          "the rows' numbering (consecutive landmarks' line and direction) also decides "
          "contested places and which of two landmarks out of sequence stays");
  v.section("row", "the numbering along a row of bays", [&] { describe(v, o.row); });
}

void describe(OptionVisitor& v, mapping::EstimationOptions& o) {
  v.value("pixel_sigma", o.pixel_sigma, "corner noise of the spotter, pixels (1 sigma)");
  v.value("estimate_corner_margin", o.estimate_corner_margin,
          "estimate each drive's corner margins: what the ink fits and the detector's boxes "
          "add around the glyphs (pixels)");
  v.value("margin_prior_sigma_px", o.margin_prior_sigma_px,
          "... under a prior of this sigma (pixels)");
  v.value("robust_scale", o.robust_scale,
          "Cauchy loss scale in sigmas: a corner off by much more is mostly ignored");
  v.value("odometry_min_sigma_m", o.odometry_min_sigma_m,
          "odometry position noise between frame sets, floor (m, 1 sigma)");
  v.value("odometry_sigma_per_m", o.odometry_sigma_per_m,
          "... and its share of the distance (slip), where the drive's scale is not estimated");
  v.value("odometry_calibrated_sigma_per_m", o.odometry_calibrated_sigma_per_m,
          "... and where it is (the white noise left once the scale error is estimated)");
  v.value("odometry_min_yaw_sigma_rad", o.odometry_min_yaw_sigma_rad,
          "odometry yaw noise between frame sets, floor (rad)");
  v.value("odometry_yaw_sigma_per_m", o.odometry_yaw_sigma_per_m,
          "... and per metre driven (rad/m; gyro noise)");
  v.value("estimate_odometry_calibration", o.estimate_odometry_calibration,
          "estimate each drive's odometry distance scale and gyro yaw-rate bias with the poses");
  v.value("calibration_min_distance_m", o.calibration_min_distance_m,
          "... over drives at least this long (m); shorter ones take the odometry as measured");
  v.value("distance_scale_prior_sigma", o.distance_scale_prior_sigma,
          "prior on the distance scale (share of the distance, 1 sigma)");
  v.value("yaw_rate_bias_prior_sigma", o.yaw_rate_bias_prior_sigma,
          "prior on the yaw-rate bias (rad/s, 1 sigma)");
  v.value("max_iterations", o.max_iterations, "Ceres iterations at most");
  v.value("threads", o.threads, "Ceres threads");
}

}  // namespace

void describe(OptionVisitor& v, mapping::MapBuildOptions& o) {
  v.section("reading", "what is read on every frame set", [&] { describe(v, o.reading); });
  v.section("consensus", "which sightings are one text, and what it says",
            [&] { describe(v, o.consensus); });
  v.section("estimation", "poses and landmarks by Ceres", [&] { describe(v, o.estimation); });
  v.value("odometry_scale_tolerance", o.odometry_scale_tolerance,
          "beyond this relative distance difference the odometry disagrees with the cameras");
  v.value("max_median_px", o.max_median_px,
          "a landmark whose corners reproject worse (median, px) is no floor text: left out");
  v.value("max_rms_px", o.max_rms_px,
          "... or worse in the RMS (px): a box over a pillar's text and the floor");
  v.section("stencil", "one stencil paints a level's numbers: a height far off it takes it", [&] {
    v.value("tolerance", o.stencil.tolerance,
            "a landmark whose height is off its class's median by more than this share takes "
            "the median (0: every height as estimated)");
    v.value("min_landmarks", o.stencil.min_landmarks,
            "... in a class of at least this many landmarks");
  });
}

}  // namespace parkloc::config
