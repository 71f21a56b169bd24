#include "geometry/text_polygon.h"

#include <cmath>

namespace parkloc::geometry {

double apparentHeightPx(const TextPolygon& p) {
  const Eigen::Vector2d d1 = p[2] - p[0], d2 = p[3] - p[1];
  const double area = 0.5 * std::abs(d1.x() * d2.y() - d1.y() * d2.x());
  const double length = readingLengthPx(p);
  return length > 0.0 ? area / length : 0.0;
}

double readingLengthPx(const TextPolygon& p) {
  return 0.5 * ((p[1] - p[0]).norm() + (p[2] - p[3]).norm());
}

}  // namespace parkloc::geometry
