#pragma once
// Clocks for FrameResult::timings: the wall-clock time of each stage of a frame set and the
// CPU time of the whole process over it.
#include <chrono>

namespace parkloc::localize {

// Wall-clock time since construction (a monotonic clock: never negative).
class Stopwatch {
 public:
  Stopwatch() : start_(Clock::now()) {}
  double elapsedMs() const {
    return std::chrono::duration<double, std::milli>(Clock::now() - start_).count();
  }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_;
};

// CPU time of the process so far, all threads (the OCR engine's included), milliseconds.
double processCpuMs();

}  // namespace parkloc::localize
