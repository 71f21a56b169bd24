#include "io/anchors_csv.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "common/error.h"

namespace parkloc::io {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

}  // namespace

std::vector<Anchor> loadAnchors(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("anchors {}: cannot read the file", path));
  std::vector<Anchor> anchors;
  std::set<std::string> seen;
  std::string line;
  int number = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++number;
    line = trim(line);
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> fields;
    std::stringstream row(line);
    for (std::string field; std::getline(row, field, ',');) fields.push_back(trim(field));
    if (!header) {
      if (fields != std::vector<std::string>{"text", "x", "y"})
        throw InputError(
            fmt::format("anchors {} line {}: expected the header 'text,x,y'", path, number));
      header = true;
      continue;
    }
    if (fields.size() != 3 || fields[0].empty())
      throw InputError(fmt::format("anchors {} line {}: expected text,x,y", path, number));
    Anchor a;
    a.text = fields[0];
    for (int k = 0; k < 2; ++k) {
      char* end = nullptr;
      const std::string& f = fields[static_cast<size_t>(k + 1)];
      a.position[k] = std::strtod(f.c_str(), &end);
      if (f.empty() || end != f.c_str() + f.size() || !std::isfinite(a.position[k]))
        throw InputError(
            fmt::format("anchors {} line {}: '{}' is not a finite number", path, number, f));
    }
    if (!seen.insert(a.text).second)
      throw InputError(fmt::format("anchors {} line {}: '{}' given twice", path, number, a.text));
    anchors.push_back(std::move(a));
  }
  if (!header) throw InputError(fmt::format("anchors {}: empty (no 'text,x,y' header)", path));
  return anchors;
}

}  // namespace parkloc::io
