#include "io/odometry_csv.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>

#include "common/error.h"
#include "io/csv_file.h"

namespace parkloc::io {
namespace {
constexpr const char* kHeader = "timestamp,speed,yaw_rate";

}  // namespace

std::vector<OdometrySample> loadOdometry(const std::string& path) {
  std::ifstream in = openCsvWithHeader("odometry", path, kHeader);
  std::string line;
  size_t line_no = 1;
  std::vector<OdometrySample> samples;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string row = trimmed(line);
    if (row.empty()) continue;
    double v[3];
    const char* p = row.c_str();
    for (int i = 0; i < 3; ++i) {
      char* end = nullptr;
      v[i] = std::strtod(p, &end);
      const char expected = i < 2 ? ',' : '\0';
      while (end != p && (*end == ' ' || *end == '\t')) ++end;
      if (end == p || *end != expected)
        throw InputError(
            fmt::format("odometry {}:{}: malformed row '{}' (expected 'timestamp,speed,yaw_rate')",
                        path, line_no, row));
      if (!std::isfinite(v[i]))
        throw InputError(
            fmt::format("odometry {}:{}: non-finite value in column {}", path, line_no, i + 1));
      p = end + 1;
    }
    if (!samples.empty() && !(v[0] > samples.back().timestamp))
      throw InputError(
          fmt::format("odometry {}:{}: timestamp {} is not after the previous one ({})", path,
                      line_no, v[0], samples.back().timestamp));
    samples.push_back({v[0], v[1], v[2]});
  }
  return samples;
}

void saveOdometry(const std::vector<OdometrySample>& samples, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw IoError(fmt::format("odometry {}: cannot open for writing", path));
  out << kHeader << "\n";
  // Shortest round-trip form: a reload gives back exactly the same doubles.
  for (const OdometrySample& s : samples)
    out << fmt::format("{},{},{}\n", s.timestamp, s.speed, s.yaw_rate);
  if (!out) throw IoError(fmt::format("odometry {}: write failed", path));
}

}  // namespace parkloc::io
