#pragma once
// A line of a text format cut at a separator into its fields, empty ones kept: "a,,b," gives
// "a", "", "b", "". For the small formats parkloc reads by hand (fault specs, labels.tsv).
#include <sstream>
#include <string>
#include <vector>

namespace parkloc {

inline std::vector<std::string> splitFields(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::istringstream in(text);
  for (std::string part; std::getline(in, part, separator);) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.emplace_back();
  return parts;
}

}  // namespace parkloc
