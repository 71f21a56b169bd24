#pragma once
// One instance per text: the detectors of a spotter look at overlapping images (the floor view,
// its windows, the horizon band, the raw image), and what a later one finds again is dropped.
#include <vector>

#include "ocr/text_spotter.h"

namespace parkloc::ocr {

// Whether `inst`'s centre lies in the polygon (raw image pixels) of one of the first `count`
// of `found`.
bool seenBefore(const TextInstance& inst, const std::vector<TextInstance>& found, size_t count);

// Appends to `out` each of `found` that no instance already in `out` holds (seenBefore).
void appendUnseen(std::vector<TextInstance>& out, std::vector<TextInstance> found);

}  // namespace parkloc::ocr
