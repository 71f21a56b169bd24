#include <algorithm>

#include "localize/read_planning.h"

namespace parkloc::localize {

FullFrameChoice FullFrameSchedule::next(size_t n_cameras, bool tracking, bool initialised,
                                        bool tentative, std::optional<int> worker_slots) {
  FullFrameChoice choice;
  int interval = std::max(1, options_.full_frame_interval);
  // A tentative track sweeps more often: what the wrong pose's prediction misses is the
  // texts that would tell it is wrong.
  if (tentative && options_.tentative_full_frame_interval > 1)
    interval = std::min(interval, options_.tentative_full_frame_interval);
  // How many cameras' full frames can be taken now: no limit inside the frame set.
  const bool taken = !worker_slots || *worker_slots > 0;
  const size_t takers = worker_slots ? static_cast<size_t>(std::max(0, *worker_slots)) : 1;
  choice.all = !guided_ || !tracking || interval == 1 ||
               (!options_.full_frame_round_robin && frames_since_full_frame_ + 1 >= interval);
  frames_since_full_frame_ = choice.all ? 0 : frames_since_full_frame_ + 1;
  choice.full_frame.assign(n_cameras, choice.all && taken);
  if (!choice.all && options_.full_frame_round_robin && n_cameras > 0) {
    // One camera per slot, n_cameras slots spread evenly over every `interval` tracking
    // frame sets: the same full-frame images as all cameras every `interval` frame sets, but
    // never more than one in a frame set (the p99 latency). A slot that finds no worker free
    // waits for one.
    const long t = tracking_frames_;
    const long per = static_cast<long>(n_cameras);
    if ((t + 1) * per / interval > t * per / interval) sweep_waiting_ = true;
    if (sweep_waiting_ && taken) {
      choice.full_frame[next_sweep_camera_ % n_cameras] = true;
      next_sweep_camera_ = (next_sweep_camera_ + 1) % n_cameras;
      choice.sweeping = true;
      sweep_waiting_ = false;
    }
  }
  if (!tracking) sweep_waiting_ = false;
  // Searching (no pose yet): the full frame of a few cameras per frame set (per free worker),
  // in turn.
  choice.searching = guided_ && !initialised && interval > 1;
  const int per_search = options_.search_cameras_per_frame;
  if (choice.searching && per_search > 0 && static_cast<size_t>(per_search) < n_cameras) {
    const size_t count = std::min(n_cameras, static_cast<size_t>(per_search) * takers);
    choice.full_frame.assign(n_cameras, false);
    for (size_t k = 0; k < count; ++k)
      choice.full_frame[(next_search_camera_ + k) % n_cameras] = true;
    next_search_camera_ = (next_search_camera_ + count) % n_cameras;
  }
  tracking_frames_ = tracking ? tracking_frames_ + 1 : 0;
  return choice;
}

}  // namespace parkloc::localize
