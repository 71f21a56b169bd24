#include "eval/photo_recall.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <fstream>

#include "common/error.h"
#include "common/split_fields.h"

namespace parkloc::eval {
namespace {

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return s;
}

bool ascii(const std::string& s) {
  return std::all_of(s.begin(), s.end(), [](unsigned char c) { return c >= 0x20 && c < 0x7f; });
}

}  // namespace

std::vector<PhotoLabels> loadPhotoLabels(const std::string& folder) {
  const std::string path = folder + "/labels.tsv";
  std::ifstream in(path);
  if (!in) throw IoError(path + ": file not found");
  std::vector<PhotoLabels> photos;
  std::string line;
  for (int line_no = 1; std::getline(in, line); ++line_no) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::vector<std::string> fields = splitFields(line, '\t');
    if (fields.size() < 4 || fields[0].empty())
      throw InputError(
          fmt::format("{}: line {}: expected FILE, SOURCE_REPO, SOURCE_PATH and "
                      "TOKENS separated by tabs",
                      path, line_no));
    PhotoLabels photo{fields[0], {}};
    for (std::string token : splitFields(fields[3], '|')) {
      if (token.rfind("[P]", 0) == 0) token.erase(0, 3);
      if (!token.empty()) photo.tokens.push_back(token);
    }
    photos.push_back(std::move(photo));
  }
  if (photos.empty()) throw InputError(path + ": no labelled photo");
  return photos;
}

std::vector<std::string> scoredTokens(const PhotoLabels& labels) {
  std::vector<std::string> scored;
  for (const std::string& t : labels.tokens)
    if (t.size() >= 2 && ascii(t)) scored.push_back(t);
  return scored;
}

int tokensRead(const std::vector<std::string>& tokens, const std::vector<std::string>& readings) {
  std::vector<std::string> read_upper;
  for (const std::string& r : readings) read_upper.push_back(upper(r));
  int read = 0;
  for (const std::string& token : tokens) {
    const std::string t = upper(token);
    if (std::any_of(read_upper.begin(), read_upper.end(),
                    [&](const std::string& r) { return r.find(t) != std::string::npos; }))
      ++read;
  }
  return read;
}

}  // namespace parkloc::eval
