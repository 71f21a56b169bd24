#pragma once
// A label's polygon (Eigen corners, as io::LabelInstance and geometry hold it) as OpenCV
// points (ocr::Quad's type, as the spotter and the metrics hold it), and back; the corner
// order is kept: top-left, top-right, bottom-right, bottom-left of the text as it reads.
#include <array>
#include <opencv2/core.hpp>

#include "geometry/text_polygon.h"

namespace parkloc::io {

using PointQuad = std::array<cv::Point2f, 4>;

PointQuad pointQuad(const geometry::TextPolygon& polygon);
geometry::TextPolygon textPolygon(const PointQuad& quad);

}  // namespace parkloc::io
