#include "run/replay_summary.h"

#include <algorithm>
#include <limits>

#include "run/percentile.h"

namespace parkloc::run {

ReplaySummary summarizeReplays(const std::vector<RunSummary>& runs) {
  ReplaySummary r;
  r.replays = runs.size();
  std::vector<double> ages;
  r.first_pose_frame_min = std::numeric_limits<size_t>::max();
  r.first_pose_ms_min = std::numeric_limits<double>::infinity();
  for (const RunSummary& s : runs) {
    ages.insert(ages.end(), s.pose_age_ms.begin(), s.pose_age_ms.end());
    r.dropped += s.frames_dropped;
    r.frames += s.frames + s.frames_dropped;
    if (!s.first_pose_frame) continue;
    ++r.posed;
    r.mean_error_m += s.mean_position_error_m;
    r.p95_error_m += s.p95_position_error_m;
    r.first_pose_frame_min = std::min(r.first_pose_frame_min, *s.first_pose_frame);
    r.first_pose_frame_max = std::max(r.first_pose_frame_max, *s.first_pose_frame);
    r.first_pose_ms_min = std::min(r.first_pose_ms_min, s.first_pose_output_ms);
    r.first_pose_ms_max = std::max(r.first_pose_ms_max, s.first_pose_output_ms);
  }
  if (r.posed == 0) {
    r.first_pose_frame_min = 0;
    r.first_pose_ms_min = 0.0;
  } else {
    r.mean_error_m /= static_cast<double>(r.posed);
    r.p95_error_m /= static_cast<double>(r.posed);
  }
  r.age_median_ms = percentile(ages, 0.5);
  r.age_p95_ms = percentile(ages, 0.95);
  r.age_p99_ms = percentile(ages, 0.99);
  r.age_max_ms = percentile(ages, 1.0);
  return r;
}

}  // namespace parkloc::run
