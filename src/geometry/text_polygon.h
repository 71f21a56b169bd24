#pragma once
// Sizes of a text's image quadrilateral (corners in reading order: top-left, top-right,
// bottom-right, bottom-left), shared by the simulator's legibility rule and the metrics.
#include <Eigen/Core>
#include <array>

namespace parkloc::geometry {

using TextPolygon = std::array<Eigen::Vector2d, 4>;

// Apparent height in pixels: the polygon's area over its reading length (the mean of its
// top and bottom edges). A text seen at a grazing angle is a thin sliver even when its side
// edges are long, and this measure says so. 0 for a degenerate polygon.
double apparentHeightPx(const TextPolygon& polygon);
// Reading length in pixels: the mean of the top and bottom edges.
double readingLengthPx(const TextPolygon& polygon);

}  // namespace parkloc::geometry
