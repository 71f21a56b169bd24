#include "sim/level_schedule.h"

#include <fmt/format.h>

#include "common/error.h"

namespace parkloc::sim {

Stretch LevelSchedule::stretchAt(double t) const {
  if (!changesLevel() || t < ramp_start) return Stretch::kStartLevel;
  return t < ramp_end ? Stretch::kRamp : Stretch::kEndLevel;
}

const std::string& LevelSchedule::levelAt(double t) const {
  return stretchAt(t) == Stretch::kEndLevel ? end_level : start_level;
}

LevelSchedule levelSchedule(const DriveSpec& spec, const std::string& level, double duration) {
  LevelSchedule s;
  s.start_level = level;
  s.end_level = spec.to_level.empty() ? level : spec.to_level;
  if (!s.changesLevel()) return s;
  s.ramp_start = spec.transition_at_s < 0.0 ? 0.5 * (spec.duration_s - spec.transition_s)
                                            : spec.transition_at_s;
  s.ramp_end = s.ramp_start + spec.transition_s;
  if (!(s.ramp_start > 0.0 && s.ramp_end < duration))
    throw InputError(
        fmt::format("scenario: the ramp from {} to {} ({:.2f} s to {:.2f} s) does not fit in the "
                    "{:.2f} s drive",
                    s.start_level, s.end_level, s.ramp_start, s.ramp_end, duration));
  return s;
}

}  // namespace parkloc::sim
