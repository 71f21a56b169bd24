#include "io/levels_csv.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>

#include "common/error.h"
#include "io/csv_file.h"

namespace parkloc::io {
namespace {

constexpr const char* kHeader = "timestamp,level";
constexpr double kTimeSlack = 1e-6;


// The reason a level name cannot stand in a row, or empty when it can.
std::string badLevelName(const std::string& level) {
  if (level.empty()) return "empty level name";
  for (const char c : level) {
    if (c == ',') return fmt::format("level name '{}' holds a comma", level);
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      return "level name holds a control character";
  }
  return "";
}

}  // namespace

std::vector<StampedLevel> loadLevels(const std::string& path) {
  std::ifstream in = openCsvWithHeader("levels", path, kHeader);
  std::string line;
  std::vector<StampedLevel> levels;
  for (size_t line_no = 2; std::getline(in, line); ++line_no) {
    const std::string row = trimmed(line);
    if (row.empty()) continue;
    const size_t comma = row.find(',');
    if (comma == std::string::npos || row.find(',', comma + 1) != std::string::npos)
      throw InputError(fmt::format("levels {}:{}: malformed row '{}' (expected 'timestamp,level')",
                                   path, line_no, row));
    const std::string stamp = trimmed(row.substr(0, comma));
    char* end = nullptr;
    const double t = std::strtod(stamp.c_str(), &end);
    if (stamp.empty() || end != stamp.c_str() + stamp.size())
      throw InputError(
          fmt::format("levels {}:{}: timestamp '{}' is not a number", path, line_no, stamp));
    if (!std::isfinite(t))
      throw InputError(fmt::format("levels {}:{}: non-finite timestamp", path, line_no));
    if (!levels.empty() && !(t > levels.back().timestamp))
      throw InputError(fmt::format("levels {}:{}: timestamp {} is not after the previous one ({})",
                                   path, line_no, t, levels.back().timestamp));
    StampedLevel s{t, trimmed(row.substr(comma + 1))};
    if (const std::string why = badLevelName(s.level); !why.empty())
      throw InputError(fmt::format("levels {}:{}: {}", path, line_no, why));
    levels.push_back(std::move(s));
  }
  return levels;
}

void saveLevels(const std::vector<StampedLevel>& levels, const std::string& path) {
  for (const StampedLevel& s : levels)
    if (const std::string why = badLevelName(s.level); !why.empty())
      throw InputError(
          fmt::format("levels {}: cannot write the row at {}: {}", path, s.timestamp, why));
  std::ofstream out(path);
  if (!out) throw IoError(fmt::format("levels {}: cannot open for writing", path));
  out << kHeader << "\n";
  // The timestamps as poses.tum prints them (io/tum.cc), so the two files list the same times.
  for (const StampedLevel& s : levels) out << fmt::format("{:.9f},{}\n", s.timestamp, s.level);
  if (!out) throw IoError(fmt::format("levels {}: write failed", path));
}

std::optional<std::string> levelAt(const std::vector<StampedLevel>& levels, double t) {
  const auto after =
      std::upper_bound(levels.begin(), levels.end(), t + kTimeSlack,
                       [](double time, const StampedLevel& s) { return time < s.timestamp; });
  if (after == levels.begin()) return std::nullopt;
  return std::prev(after)->level;
}

}  // namespace parkloc::io
