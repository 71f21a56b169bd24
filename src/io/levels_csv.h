#pragma once
// Ground truth of the garage level per frame set, as CSV with the header "timestamp,level":
// seconds (the timestamps of poses.tum, nine decimals) and the level's name as the map has it
// ("B2"). `parkloc simulate` writes levels.csv next to poses.tum; evaluation reads it, the
// estimator never does.
#include <optional>
#include <string>
#include <vector>

namespace parkloc::io {

struct StampedLevel {
  double timestamp = 0.0;
  std::string level;
};

// Throws InputError naming the file and line for a missing header, a row that is not
// "timestamp,level", a timestamp that is not a finite number or not after the previous one,
// or an empty level name.
std::vector<StampedLevel> loadLevels(const std::string& path);
// Throws InputError for a level name a row cannot hold (empty, a comma, a control character),
// IoError when the file cannot be written.
void saveLevels(const std::vector<StampedLevel>& levels, const std::string& path);

// The level at time t: that of the last row at or before t, with 1 microsecond of slack (the
// precision of image file names, io::timestampStem); none before the first row.
std::optional<std::string> levelAt(const std::vector<StampedLevel>& levels, double t);

}  // namespace parkloc::io
