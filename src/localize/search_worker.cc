#include "localize/search_worker.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <ctime>
#include <exception>

#include "localize/stage_clock.h"

namespace parkloc::localize {
namespace {

double threadCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

}  // namespace

SearchWorker::SearchWorker(ocr::TextSpotter* spotter, int nice)
    : spotter_(spotter), thread_([this, nice] { run(nice); }) {}

SearchWorker::~SearchWorker() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

bool SearchWorker::busy() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return busy_;
}

void SearchWorker::submit(SearchJob job) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (busy_) return;
    job_ = std::move(job);
    busy_ = true;
  }
  changed_.notify_all();
}

std::optional<SearchResult> SearchWorker::poll() {
  std::lock_guard<std::mutex> lock(mutex_);
  return takeResult();
}

std::optional<SearchResult> SearchWorker::wait() {
  std::unique_lock<std::mutex> lock(mutex_);
  if (!busy_) return std::nullopt;
  changed_.wait(lock, [&] { return result_.has_value(); });
  return takeResult();
}

std::optional<SearchResult> SearchWorker::waitUntil(
    std::chrono::steady_clock::time_point deadline) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (!busy_) return std::nullopt;
  changed_.wait_until(lock, deadline, [&] { return result_.has_value(); });
  return takeResult();
}

std::optional<SearchResult> SearchWorker::takeResult() {
  if (!result_) return std::nullopt;
  std::optional<SearchResult> out = std::move(result_);
  result_.reset();
  busy_ = false;
  return out;
}

void SearchWorker::run(int nice) {
  // Linux gives each thread its own nice value; elsewhere this changes nothing that matters.
  if (nice != 0) setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), nice);
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return stop_ || job_.has_value(); });
    if (!job_) return;  // stopping with nothing in hand
    const SearchJob job = std::move(*job_);
    job_.reset();
    lock.unlock();
    SearchResult result = spot(job);
    lock.lock();
    result_ = std::move(result);
    changed_.notify_all();
  }
}

SearchResult SearchWorker::spot(const SearchJob& job) const {
  const Stopwatch wall;
  const double cpu_start = threadCpuMs();
  SearchResult r;
  r.frame = job.frame;
  r.timestamp = job.timestamp;
  r.cameras = job.cameras;
  r.instances.resize(job.cameras.size());
  r.errors.resize(job.cameras.size());
  for (size_t k = 0; k < job.cameras.size(); ++k) {
    // An exception must not end the thread (std::terminate): it is reported with the camera.
    try {
      r.instances[k] = spotter_->spot(job.images[k], job.requests[k]);
    } catch (const std::exception& e) {
      r.errors[k] = e.what();
    }
  }
  r.wall_ms = wall.elapsedMs();
  r.cpu_ms = threadCpuMs() - cpu_start;
  return r;
}

}  // namespace parkloc::localize
