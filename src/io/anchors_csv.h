#pragma once
// Anchors: landmarks whose map position is known (surveyed), which put a built map into that
// frame. CSV with the header "text,x,y" (metres, map frame); lines starting with '#' are
// comments. Example:
//   text,x,y
//   B001,7.75,11.88
//   B015,42.75,11.88
#include <Eigen/Core>
#include <string>
#include <vector>

namespace parkloc::io {

struct Anchor {
  std::string text;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
};

// Throws InputError naming the file and line for an unreadable file, a missing header, a
// malformed row, a non-finite number or a text given twice.
std::vector<Anchor> loadAnchors(const std::string& path);

}  // namespace parkloc::io
