#pragma once
// The part of a text quad that an image shows, for text cut by the image's edge: a detector
// can only box what it sees, and ICDAR-style truth annotates only that.
#include <functional>
#include <opencv2/core.hpp>
#include <optional>

#include "ocr/quad.h"

namespace parkloc::ocr {

struct VisiblePart {
  Quad quad;                    // the visible span, in the text's reading order
  float length_fraction = 0.f;  // of the reading direction's length that it keeps
  float height_fraction = 0.f;  // of the height across it
};

struct VisiblePartOptions {
  int samples_along = 32;  // grid over the quad, along the reading direction
  int samples_across = 8;  // and across it
  float min_share = 0.5f;  // a grid column (row) counts as seen when this share of it is
};

// The smallest span [u0, u1] x [v0, v1] of the quad's bilinear parameters that holds every
// grid column and row seen (`visible` true at their points); empty when nothing is seen. The
// span is one piece: a text cut by an edge loses its ends, never its middle.
std::optional<VisiblePart> visiblePart(const Quad& quad,
                                       const std::function<bool(const cv::Point2f&)>& visible,
                                       const VisiblePartOptions& options = {});

}  // namespace parkloc::ocr
