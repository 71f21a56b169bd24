#pragma once
// Which level a drive is on at each moment. A drive that changes level (DriveSpec::to_level)
// is on its start level until the ramp begins, on the ramp between the floors (no text in
// view, sim/ramp_level.h) for the ramp's seconds, and on the other level after it.
#include <string>

#include "sim/scenario.h"

namespace parkloc::sim {

enum class Stretch { kStartLevel, kRamp, kEndLevel };

struct LevelSchedule {
  std::string start_level;
  std::string end_level;    // the start level when the drive stays on it
  double ramp_start = 0.0;  // seconds from the start of the drive; the ramp is
  double ramp_end = 0.0;    // [ramp_start, ramp_end), only when changesLevel()

  bool changesLevel() const { return end_level != start_level; }
  Stretch stretchAt(double t) const;
  // The level a frame at time t belongs to, its ground truth: the level the car drove on last.
  // On the ramp it is still the level the car left (no text of either is in view); the other
  // level begins with the first moment past the ramp.
  const std::string& levelAt(double t) const;
};

// The schedule of `spec` driven from `level` over a drive of `duration` seconds: the ramp at
// spec.transition_at_s, or centred in spec.duration_s when that is negative (a tour is cut at
// duration_s, a hair short of it). Throws InputError when the ramp does not end before the
// drive does.
LevelSchedule levelSchedule(const DriveSpec& spec, const std::string& level, double duration);

}  // namespace parkloc::sim
