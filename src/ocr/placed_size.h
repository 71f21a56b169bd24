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
  // A box that matched no text is held to the size of the text whose footprint on the floor,
  // grown by this margin (metres), holds its centre (fitUnmatchedToPlacedSize). Negative: never.
  double unmatched_margin_m = 0.1;
  // ... when its reading axis lies within this angle (radians) of the way that text reads.
  float unmatched_max_angle = 0.5236f;  // 30 degrees
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

// A box that matched no text but lies on one and along it (its reading axis within
// options.unmatched_max_angle of `reading`, either way round) is that text's box, or a fragment
// of it: tightened like a whole match, or refused when under min_length_share of the text's
// length (a fragment is no box of the text). Across the text it is kept as it is.
PlacedSizeFit fitUnmatchedToPlacedSize(const Quad& quad, float width, float height,
                                       const cv::Point2f& reading,
                                       const PlacedSizeOptions& options = {});

}  // namespace parkloc::ocr
