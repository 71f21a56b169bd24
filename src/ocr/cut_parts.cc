#include "ocr/cut_parts.h"

#include <algorithm>
#include <map>

#include "ocr/ctc.h"
#include "ocr/lexicon.h"

namespace parkloc::ocr {

std::vector<std::string> partsLeftByACut(const std::string& text, bool cut_at_start,
                                         bool cut_at_end, size_t min_chars) {
  const std::vector<std::string> chars = splitUtf8(text);
  std::vector<std::string> parts;
  auto join = [&](size_t from, size_t to) {
    std::string s;
    for (size_t i = from; i < to; ++i) s += chars[i];
    return s;
  };
  for (size_t k = chars.size() > 0 ? chars.size() - 1 : 0; k >= std::max<size_t>(min_chars, 1);
       --k) {
    if (cut_at_start) parts.push_back(join(chars.size() - k, chars.size()));
    if (cut_at_end) parts.push_back(join(0, k));
  }
  return parts;
}

CutCandidates withCutParts(const std::vector<std::string>& wholes, bool cut_at_start,
                           bool cut_at_end, size_t min_chars) {
  CutCandidates out{wholes, wholes};
  std::map<std::string, std::vector<std::string>> owners;  // part -> the wholes that leave it
  std::vector<std::string> order;
  for (const std::string& whole : wholes) {
    const size_t half = (splitUtf8(whole).size() + 1) / 2;
    for (const std::string& part :
         partsLeftByACut(whole, cut_at_start, cut_at_end, std::max(min_chars, half))) {
      auto& o = owners[part];
      if (o.empty()) order.push_back(part);
      if (std::find(o.begin(), o.end(), whole) == o.end()) o.push_back(whole);
    }
  }
  for (const std::string& part : order) {
    const auto& o = owners[part];
    if (o.size() != 1 || std::find(wholes.begin(), wholes.end(), part) != wholes.end()) continue;
    out.texts.push_back(part);
    out.whole.push_back(o.front());
  }
  return out;
}

std::optional<std::string> wholeOfPart(const std::string& reading,
                                       const CutCandidates& candidates) {
  std::optional<std::string> whole;
  for (size_t i = 0; i < candidates.texts.size(); ++i) {
    const std::string& text = candidates.texts[i];
    if (text != reading && !sameUpToLookAlikes(text, reading)) continue;
    if (text == candidates.whole[i]) return std::nullopt;  // a whole text, no part
    if (whole && *whole != candidates.whole[i]) return std::nullopt;
    whole = candidates.whole[i];
  }
  return whole;
}

}  // namespace parkloc::ocr
