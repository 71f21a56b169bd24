#include "io/csv_file.h"

#include <fmt/format.h>

#include "common/error.h"

namespace parkloc::io {

std::string trimmed(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const size_t e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::ifstream openCsvWithHeader(const std::string& kind, const std::string& path,
                                const std::string& header) {
  std::ifstream in(path);
  if (!in) throw IoError(fmt::format("{} {}: cannot open file", kind, path));
  std::string line;
  if (!std::getline(in, line) || trimmed(line) != header)
    throw InputError(fmt::format("{} {}:1: expected the header '{}'", kind, path, header));
  return in;
}

}  // namespace parkloc::io
