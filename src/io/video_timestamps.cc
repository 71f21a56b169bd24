#include "io/video_timestamps.h"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>

#include "common/error.h"
#include "io/csv_file.h"

namespace parkloc::io {
namespace {

constexpr const char* kHeader = "frame,timestamp";


}  // namespace

std::vector<VideoFrameTime> loadVideoTimestamps(const std::string& path) {
  std::ifstream in = openCsvWithHeader("timestamps", path, kHeader);
  std::string line;
  std::vector<VideoFrameTime> rows;
  for (size_t line_no = 2; std::getline(in, line); ++line_no) {
    const std::string row = trimmed(line);
    if (row.empty()) continue;
    const auto fail = [&](const std::string& why) {
      return InputError(fmt::format("timestamps {}:{}: {}", path, line_no, why));
    };
    const size_t comma = row.find(',');
    if (comma == std::string::npos || row.find(',', comma + 1) != std::string::npos)
      throw fail(fmt::format("malformed row '{}' (expected 'frame,timestamp')", row));
    const std::string frame_text = trimmed(row.substr(0, comma));
    const std::string time_text = trimmed(row.substr(comma + 1));
    char* end = nullptr;
    errno = 0;
    const long frame = std::strtol(frame_text.c_str(), &end, 10);
    if (frame_text.empty() || end != frame_text.c_str() + frame_text.size() || errno != 0 ||
        frame < 0 || frame > std::numeric_limits<int>::max())
      throw fail(fmt::format("frame '{}' is not a frame index (0, 1, 2, ...)", frame_text));
    const double t = std::strtod(time_text.c_str(), &end);
    if (time_text.empty() || end != time_text.c_str() + time_text.size())
      throw fail(fmt::format("timestamp '{}' is not a number", time_text));
    if (!std::isfinite(t)) throw fail("non-finite timestamp");
    if (!rows.empty() && frame <= rows.back().frame)
      throw fail(fmt::format("frame {} does not follow frame {}", frame, rows.back().frame));
    if (!rows.empty() && !(t > rows.back().timestamp))
      throw fail(fmt::format("timestamp {} is not after the previous one ({})", t,
                             rows.back().timestamp));
    rows.push_back({static_cast<int>(frame), t});
  }
  if (rows.empty()) throw InputError(fmt::format("timestamps {}: no frames", path));
  return rows;
}

}  // namespace parkloc::io
