#pragma once
// A number cut by the image border shows only one end of itself ("008" of "C008"), which no
// lexicon entry is. Where the map says which text lies under a box (a predicted pose places
// one or two there) and the box may run out of the image, the parts a cut can leave of those
// texts are candidates too, each standing for its whole text. Parts that two texts share, or
// that are another text whole, stand for nothing and are left out.
#include <optional>
#include <string>
#include <vector>

namespace parkloc::ocr {

// The parts a cut leaves of `text` (UTF-8): with `cut_at_start` its last k characters, with
// `cut_at_end` its first k, for k from `min_chars` to its length less one; longest first.
std::vector<std::string> partsLeftByACut(const std::string& text, bool cut_at_start,
                                         bool cut_at_end, size_t min_chars);

struct CutCandidates {
  std::vector<std::string> texts;  // the whole texts, then the parts of them
  std::vector<std::string> whole;  // per entry of `texts`, the whole text it stands for
};

// `wholes`, then the parts partsLeftByACut leaves of them, with at least
// max(min_chars, half the whole's length rounded up) characters; a part shared by two wholes,
// or equal to a whole, is left out.
CutCandidates withCutParts(const std::vector<std::string>& wholes, bool cut_at_start,
                           bool cut_at_end, size_t min_chars);

// The whole text of the part of `candidates` that `reading` is, exactly or up to glyphs that
// look alike (sameUpToLookAlikes); empty when it is a whole text itself, no part, or parts of
// two texts.
std::optional<std::string> wholeOfPart(const std::string& reading, const CutCandidates& candidates);

}  // namespace parkloc::ocr
