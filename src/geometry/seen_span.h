#pragma once
// The part of a text that is seen, as a span of its own parameters: u along the reading
// direction, v across it, both in [0, 1]. A text cut by an image's edge loses its ends; a
// detector can only box what shows, and ICDAR-style truth annotates only that.
#include <functional>
#include <optional>

namespace parkloc::geometry {

struct ParameterSpan {
  double u0 = 0.0, u1 = 1.0;  // along the reading direction
  double v0 = 0.0, v1 = 1.0;  // across it
};

struct SeenSpanOptions {
  int samples_u = 32;      // grid over the text, along the reading direction
  int samples_v = 8;       // and across it
  double min_share = 0.5;  // a grid column (row) counts as seen when this share of it is
};

// The smallest span that holds every grid column and row seen (`seen(u, v)` true at their
// cell centres), in whole grid cells; empty when nothing is seen. Rows are judged over the
// seen columns only, so that a cut along the length does not hide them. The span is one
// piece: a text cut by an edge loses its ends, never its middle.
std::optional<ParameterSpan> seenSpan(const std::function<bool(double u, double v)>& seen,
                                      const SeenSpanOptions& options = {});

}  // namespace parkloc::geometry
