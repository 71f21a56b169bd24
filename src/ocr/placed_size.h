#pragma once
// A floor box read as a text that the map places near it has that text's size on the floor.
// DB grows each box by a margin that follows the box's own shape (unclip), and the corner fit
// cannot tighten a box whose ink is faint: a number seen edge-on through blur, or the sliver
// of one in front of a bumper, comes out 1.6-2 times as tall as its text and misses it by
// IoU. A box far shorter than the text it was read as is not that text at all: a blob the
// placed lexicon's prior pulled onto the number painted there. Both checks work in any frame
// with the floor's proportions (a floor view's pixels, or metres).
#include "ocr/quad.h"

namespace parkloc::ocr {

struct PlacedSizeOptions {
  // A box matched to the whole text (not to the part a cut leaves) that is shorter than this
  // share of the text's length is refused.
  float min_length_share = 0.5f;
  // A box taller (longer) than these multiples of its text is cut to the text's height
  // (length) about its centre line: only ever tightened, never grown.
  float max_height_ratio = 1.3f;
  float max_length_ratio = 1.2f;
};

enum class PlacedSize { kKept, kTightened, kRefused };

struct PlacedSizeFit {
  PlacedSize verdict = PlacedSize::kKept;
  Quad quad;  // the box, tightened when verdict is kTightened
};

// `quad` in reading order (corner 0 the text's top left as it reads); `width` and `height`
// the text's length along its reading direction and its height, in the quad's units. With
// `whole` false (a match by the part a cut leaves) only the height is checked.
PlacedSizeFit fitToPlacedSize(const Quad& quad, float width, float height, bool whole,
                              const PlacedSizeOptions& options = {});

}  // namespace parkloc::ocr
