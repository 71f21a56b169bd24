#include "io/polygon_points.h"

namespace parkloc::io {

PointQuad pointQuad(const geometry::TextPolygon& polygon) {
  PointQuad q;
  for (size_t i = 0; i < 4; ++i)
    q[i] = cv::Point2f(static_cast<float>(polygon[i].x()), static_cast<float>(polygon[i].y()));
  return q;
}

geometry::TextPolygon textPolygon(const PointQuad& quad) {
  geometry::TextPolygon p;
  for (size_t i = 0; i < 4; ++i) p[i] = Eigen::Vector2d(quad[i].x, quad[i].y);
  return p;
}

}  // namespace parkloc::io
