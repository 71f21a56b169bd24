#pragma once
// The progress line on stderr of the long commands (eval, run, demo, bench).
#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "apps/parkloc/command.h"
#include "eval/evaluation.h"

namespace parkloc::app {

// "\r<stage> [#####.....] 12/40 frame sets, 3 s, eta 7 s" on stderr, a new line per stage.
class ProgressLine {
 public:
  explicit ProgressLine(bool quiet = false) : quiet_(quiet) {}
  ~ProgressLine() { finish(); }

  void operator()(const eval::Progress& p) {
    if (quiet_) return;
    const auto now = std::chrono::steady_clock::now();
    if (p.stage != stage_) {
      finish();
      stage_ = p.stage;
      start_ = now;
    }
    const double fraction = p.total ? static_cast<double>(p.done) / p.total : 1.0;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double eta = fraction > 0 ? elapsed / fraction - elapsed : 0.0;
    const int width = 30, filled = static_cast<int>(fraction * width);
    std::cerr << fmt::format("\r{} [{}{}] {}/{} frame sets, {:.0f} s, eta {:.0f} s   ", stage_,
                             std::string(filled, '#'), std::string(width - filled, '.'), p.done,
                             p.total, elapsed, eta)
              << std::flush;
    open_ = true;
  }
  void finish() {
    if (open_) std::cerr << "\n";
    open_ = false;
  }

 private:
  bool quiet_ = false;
  bool open_ = false;
  std::string stage_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace parkloc::app
