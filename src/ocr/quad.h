#pragma once
// Text quadrilaterals: corner order and perspective-rectified crops.
#include <array>
#include <opencv2/core.hpp>
#include <optional>

namespace parkloc::ocr {

using Quad = std::array<cv::Point2f, 4>;  // TL, TR, BR, BL of the text as it reads

// Corners of a rotated rectangle in reading order, taking its long side as the reading
// direction and the direction closer to image +x (left to right) as forward. Text seen
// upside down is then ordered as if upright; shiftedBy180 gives the other reading.
Quad quadFromRotatedRect(const cv::RotatedRect& rect);

// The same quad read the other way round (TL <-> BR, TR <-> BL).
Quad shiftedBy180(const Quad& quad);

// The quad or its 180 degree turn, whichever reads along `reading` (an image direction), when
// its reading axis lies within `max_angle` radians of that direction's axis; empty when it does
// not (a box whose long side runs across the text), so that it is read both ways round.
std::optional<Quad> orientedAlong(const Quad& quad, const cv::Point2f& reading, double max_angle);

// Reading width (mean of top and bottom edges) and height (mean of left and right edges).
float quadWidth(const Quad& quad);
float quadHeight(const Quad& quad);

// The mean of the four corners.
cv::Point2f quadCentre(const Quad& quad);

// Scales the quad about its centre by `ratio_x` along the reading direction and `ratio_y`
// across it, in the quad's own perspective (through its rectifying homography), so the
// paper's "box expanded by ratio 2" is expandQuad(q, 2, 2).
Quad expandQuad(const Quad& quad, float ratio_x, float ratio_y);

// Homography from the quad to the rectangle [0, width] x [0, height] (the quad's corners
// land on the output image's outer pixel edges).
cv::Mat rectifyingHomography(const Quad& quad, int width, int height);

// The quad's content warped to an upright crop of `height` pixels, its width following the
// quad's aspect ratio within [min_width, max_width]. 8-bit BGR in, 8-bit BGR out.
cv::Mat rectifiedCrop(const cv::Mat& image, const Quad& quad, int height, int min_width,
                      int max_width);

// Maps quad corners through a 3x3 homography (CV_64F).
Quad transformQuad(const Quad& quad, const cv::Mat& homography);

}  // namespace parkloc::ocr
