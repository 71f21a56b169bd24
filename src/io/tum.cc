#include "io/tum.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "common/error.h"

namespace parkloc::io {

std::vector<StampedPose> loadTum(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw IoError(fmt::format("tum {}: cannot open file", path));
  std::vector<StampedPose> poses;
  std::string line;
  for (size_t line_no = 1; std::getline(in, line); ++line_no) {
    const size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream fields(line);
    double v[8];
    int n = 0;
    std::string token;
    while (fields >> token) {
      if (n == 8) {
        n = 9;
        break;
      }
      char* end = nullptr;
      v[n] = std::strtod(token.c_str(), &end);
      if (end != token.c_str() + token.size())
        throw InputError(fmt::format("tum {}:{}: not a number: '{}'", path, line_no, token));
      ++n;
    }
    if (n != 8)
      throw InputError(fmt::format("tum {}:{}: expected 8 columns 'timestamp tx ty tz qx qy qz qw'",
                                   path, line_no));
    for (int i = 0; i < 8; ++i)
      if (!std::isfinite(v[i]))
        throw InputError(
            fmt::format("tum {}:{}: non-finite value in column {}", path, line_no, i + 1));
    Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);
    if (q.norm() < 1e-6) throw InputError(fmt::format("tum {}:{}: zero quaternion", path, line_no));
    StampedPose p;
    p.timestamp = v[0];
    p.pose.linear() = q.normalized().toRotationMatrix();
    p.pose.translation() = Eigen::Vector3d(v[1], v[2], v[3]);
    poses.push_back(p);
  }
  return poses;
}

void saveTum(const std::vector<StampedPose>& poses, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw IoError(fmt::format("tum {}: cannot open for writing", path));
  out << "# timestamp tx ty tz qx qy qz qw\n";
  for (const StampedPose& p : poses) {
    const Eigen::Quaterniond q(p.pose.rotation());
    const Eigen::Vector3d& t = p.pose.translation();
    // Nanosecond timestamps, micrometre-and-better positions, 1e-12 quaternions.
    out << fmt::format("{:.9f} {:.9f} {:.9f} {:.9f} {:.12f} {:.12f} {:.12f} {:.12f}\n", p.timestamp,
                       t.x(), t.y(), t.z(), q.x(), q.y(), q.z(), q.w());
  }
  if (!out) throw IoError(fmt::format("tum {}: write failed", path));
}

}  // namespace parkloc::io
