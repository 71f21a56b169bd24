#pragma once
// Stage 4a of the pipeline, the level estimate: which level of the garage the vehicle drives
// on, as a probability per level of the map (a hidden Markov model over the levels).
//
// Garages repeat their plan and their parking numbers on every level, so most texts say
// nothing about the level. What does:
//   - a level sign, a text that names one of the map's levels ("B2" painted on a pillar);
//   - a text that the map has on some levels only (one level's pillar labels, "LIFT");
//   - the place: while tracking, the pose gate associates a text with the landmark where the
//     pose puts it; when the other levels have that text elsewhere or not at all, the place
//     tells the level (geometric consistency).
// Each such reading multiplies the probability of the levels it fits by a likelihood ratio
// (once per text and frame set: one pillar seen by two cameras is one reading).
//
// The level changes on a ramp, and a ramp has no parking numbers: while texts are associated
// the level holds; once no text has been associated for LevelOptions::ramp_after_s, the
// probabilities mix at a rate of level change, so that the readings after the stretch decide
// the level afresh and the estimate follows a drive to another level. A level is decided once
// its probability reaches LevelOptions::decided_probability; until then association and reading
// take every level (shared_places.h: a place the levels share still fixes x, y and yaw).
//
// Only texts that were read count: a corner fit at a predicted place (TextInstance::read
// false), a part of a text and a second opinion do not. A hint (PipelineOptions::level: the
// car entered on B1) starts the estimate decided on that level; the evidence may still move it.
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "localize/frame_types.h"
#include "map/hd_map.h"

namespace parkloc::localize {

struct LevelOptions {
  // A level with at least this probability is decided.
  double decided_probability = 0.99;
  // Likelihood ratio of one reading of a level sign for the level it names.
  double sign_ratio = 30.0;
  // Likelihood ratio of one reading of a text for the levels that have it (when not all do).
  double text_ratio = 10.0;
  // Likelihood ratio of a text associated by the pose gate for the levels that have it at
  // that place (when not all do).
  double place_ratio = 10.0;
  // No frame set moves the odds between two levels by more than this: one frame's readings
  // are not independent (one misread sign, seen by two cameras, on the same paint).
  double max_frame_ratio = 50.0;
  // A stretch with no text associated for this long (seconds) may be a ramp...
  double ramp_after_s = 1.0;
  // ...on which the level changes at this rate (per second).
  double change_rate_per_s = 0.1;
  // No level's probability falls below this: readings over many frame sets are not
  // independent (the same worn sign), and a level ruled out for good could never come back.
  double min_probability = 1e-4;
  // The probability a hint gives its level at the start.
  double hint_probability = 0.999;
  // Landmarks of two levels this close (metres, same surface and direction) are one place.
  double shared_place_m = 0.3;
  // Readings recognised with a lower score are no evidence.
  double min_recognition_score = 0.0;
};

struct LevelBelief {
  std::string level;         // the most probable level ("" for a map without levels)
  double probability = 1.0;  // its probability
  bool decided = true;
};

class LevelEstimate {
 public:
  // `hint`: a level of the map, or "" (none). Throws InputError when the map lacks the hint.
  LevelEstimate(const map::HdMap& map, const LevelOptions& options, std::string hint);
  void reset();

  const LevelBelief& belief() const { return belief_; }
  // The level association and reading keep to: the decided level, else "" (every level).
  std::string restriction() const { return belief_.decided ? belief_.level : ""; }
  const std::vector<std::string>& levels() const { return levels_; }
  const std::vector<double>& probabilities() const { return p_; }
  const LevelOptions& options() const { return options_; }

  // The chance of a level change over the time since the previous frame set (on a stretch
  // without text).
  void predict(double timestamp);
  // This frame set's readings: `associations` holds one entry per instance, cameras in order.
  // A sign naming a level the map lacks is ignored, with a warning once per text.
  void update(const std::vector<CameraResult>& cameras,
              const std::vector<Association>& associations, std::vector<std::string>& warnings);

 private:
  void decide();

  const map::HdMap& map_;
  LevelOptions options_;
  std::string hint_;
  std::vector<std::string> levels_;  // sorted
  std::vector<double> p_;
  LevelBelief belief_;
  double last_timestamp_ = 0.0;
  double last_text_time_ = 0.0;  // when a text was last associated
  bool started_ = false;
  std::set<std::string> unknown_signs_;  // warned about
};

// A text as it is compared with the map's level names: upper case, no blanks ("b 2": "B2").
std::string levelNameKey(const std::string& text);

// The level of `levels` that `text` names ("b 2" names "B2"), if any: a level sign.
std::optional<std::string> levelNamedBy(const std::vector<std::string>& levels,
                                        const std::string& text);

// Whether `text` looks like a level sign ("B2", "P1", "L3", "-1"), whether or not the map has
// that level.
bool looksLikeLevelSign(const std::string& text);

}  // namespace parkloc::localize
