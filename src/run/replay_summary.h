#pragma once
// Several real-time replays of one drive taken together (`parkloc bench --replays N`). When a
// worker's texts arrive decides which frame set fuses them, so one replay is one draw; the
// figures a mode is judged by are those of its replays together.
#include <cstddef>
#include <vector>

#include "run/sequence_runner.h"

namespace parkloc::run {

struct ReplaySummary {
  size_t replays = 0;
  size_t frames = 0;   // frame sets released, all replays (processed and dropped)
  size_t dropped = 0;  // frame sets dropped, all replays
  // Pose ages of all replays pooled (milliseconds; 0 when no replay gave a pose).
  double age_median_ms = 0.0, age_p95_ms = 0.0, age_p99_ms = 0.0, age_max_ms = 0.0;
  // The replays that gave a pose: their mean and p95 position errors averaged (metres), and
  // the range of their first poses (frame set index, and output time after the first frame
  // set's release in milliseconds).
  size_t posed = 0;
  double mean_error_m = 0.0, p95_error_m = 0.0;
  size_t first_pose_frame_min = 0, first_pose_frame_max = 0;
  double first_pose_ms_min = 0.0, first_pose_ms_max = 0.0;
};

// `runs`: RunSummary of realtime runs (RunOptions::realtime).
ReplaySummary summarizeReplays(const std::vector<RunSummary>& runs);

}  // namespace parkloc::run
