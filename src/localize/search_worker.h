#pragma once
// Full-frame spotting off the frame set's critical path. Spotting a camera's full frame costs
// 50-130 ms on two cores and all four 400-700 ms (the search before the first fix, the
// tracking sweep, re-localisation after a lost track), while a frame set's tracked fits and
// predicted reads cost a few milliseconds: run inside process(), the full frames set the
// latency tail. The worker spots them on a thread of its own while process() returns each
// frame set's pose from the cheap path; its texts are fused later, at the time their images
// were captured (late_fusion.h).
//
// The worker runs at a lower priority (a nice value, Linux schedules threads one by one) so
// that on two cores the critical path's spotting takes the cores when it needs them and the
// worker gets the rest. Its spotter must be one the critical path does not call at the same
// time (ocr::TextSpotter keeps per-call state): its own instance, or one shared behind a
// mutex (serialized_spotter.h).
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <opencv2/core.hpp>

#include "ocr/text_spotter.h"

namespace parkloc::localize {

struct RealtimeOptions {
  // Full-frame spotting runs on a worker thread and its texts are fused when ready, at the
  // time their images were captured; false: inside process(), and the frame set that carries
  // it waits for it (the latency tail: 100-700 ms on two cores).
  bool background_search = false;
  // true: the worker's texts are fused exactly fuse_after_frames frame sets after the frame
  // set whose images they come from, waiting for the worker if it is not done, so that an
  // offline run gives the same poses whatever the machine's load; false: at the first frame
  // set after the worker finished (a live drive: no frame set waits).
  bool wait_for_worker = true;
  int fuse_after_frames = 1;
  // The worker thread's nice value: on two cores the critical path must win the cores.
  int worker_nice = 10;
  // Inference threads of the worker's own spotter (the apps build it): with one, all of its
  // work runs on the worker thread at the worker's priority.
  int worker_inference_threads = 1;
  // The reads at predicted places (a region of a text not read lately: detection in a small
  // patch and the recognizer, 10-20 ms a read on two cores, the bulk of a tracked frame set's
  // time) run on a worker of their own with its own spotter, and their texts are fused like
  // the full frames', at their capture time; the critical path keeps the ink fits of the
  // texts read lately; reads due while the read worker is busy wait for a frame set that
  // finds it free. While there is no track to read for (before the first fix, lost), that
  // worker takes full frames beside the search worker, other cameras of the turn. false, or
  // without that spotter: the reads stay inside the frame set.
  bool background_reads = false;
  // At construction every spotter (the critical path's and the workers') reads a made-up full
  // frame of each camera (large dark text on grey, so that the detector, the recognizer and
  // the classifier all run), as a vehicle would before it drives off: the first inference of
  // an engine allocates its buffers and costs 2-3 times a later one, which would otherwise
  // fall on the first frame sets, the search for the first fix.
  bool warm_up = false;
  // Live (wait_for_worker false), before the first fix: a frame set waits up to this long
  // for a full frame in a worker's hands. It owes no pose yet, and a search that ends
  // within the wait starts the track on this frame set instead of the next, 100 ms later
  // at 10 Hz; the pose it then returns is at most this much older. 0: no wait. Chosen on
  // the validation drives' live replays: 40 ms brought the first pose from 102-409 ms
  // (mean 224) to 126-332 ms (mean 200), pose age max 45 ms.
  double first_fix_wait_ms = 40.0;
};

// The spotters of the workers, each owned by the caller and called by its worker alone
// (null: no spotter of its own; see Pipeline).
struct WorkerSpotters {
  ocr::TextSpotter* search = nullptr;  // full frames (background_search)
  ocr::TextSpotter* reads = nullptr;   // reads at predicted places (background_reads)
};

// The images of one frame set to spot off the critical path: full frames, or a few regions.
struct SearchJob {
  long frame = -1;  // the frame set's index in the drive
  double timestamp = 0.0;
  std::vector<size_t> cameras;  // rig indices
  std::vector<cv::Mat> images;  // owned copies
  std::vector<ocr::SpotRequest> requests;
};

// What the worker read on them.
struct SearchResult {
  long frame = -1;
  double timestamp = 0.0;
  std::vector<size_t> cameras;
  std::vector<std::vector<ocr::TextInstance>> instances;  // per job camera
  std::vector<std::string> errors;                        // per job camera; "": spotted
  double wall_ms = 0.0;  // the worker's time on the job
  double cpu_ms = 0.0;   // the worker thread's CPU time on it
};

// One worker thread that spots one job at a time.
class SearchWorker {
 public:
  // `spotter` must outlive the worker.
  SearchWorker(ocr::TextSpotter* spotter, int nice);
  // Waits for the job in hand, if any, then ends the thread.
  ~SearchWorker();
  SearchWorker(const SearchWorker&) = delete;
  SearchWorker& operator=(const SearchWorker&) = delete;

  // A job was submitted and its result not yet taken.
  bool busy() const;
  // Hands the worker a job; only when not busy.
  void submit(SearchJob job);
  // The result, when the worker has finished it (never blocks).
  std::optional<SearchResult> poll();
  // The result, waiting for the worker to finish it; nullopt when not busy.
  std::optional<SearchResult> wait();
  // The result if the worker finishes it by `deadline`; nullopt when not busy or not done.
  std::optional<SearchResult> waitUntil(std::chrono::steady_clock::time_point deadline);

 private:
  void run(int nice);
  SearchResult spot(const SearchJob& job) const;
  // The finished result, handed over (the worker free again); nullopt when there is none.
  // With mutex_ held.
  std::optional<SearchResult> takeResult();

  ocr::TextSpotter* spotter_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::optional<SearchJob> job_;
  std::optional<SearchResult> result_;
  bool busy_ = false;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace parkloc::localize
