#pragma once
// Areas of text polygons in an image: intersection over union (the overlap measure of
// ICDAR-2015 detection evaluation) and the part of a polygon the image shows, for the
// metrics and for the simulator's labels. Polygons are in pixels; a quadrilateral that is not
// convex (a bad detection) is replaced by its convex hull.
#include <array>
#include <opencv2/core.hpp>
#include <vector>

namespace parkloc::geometry {

using Quad = std::array<cv::Point2f, 4>;

double polygonArea(const std::vector<cv::Point2f>& polygon);
// Area of the intersection of the convex hulls of `a` and `b`.
double intersectionArea(const std::vector<cv::Point2f>& a, const std::vector<cv::Point2f>& b);
// 0 when both are degenerate (no area).
double polygonIoU(const std::vector<cv::Point2f>& a, const std::vector<cv::Point2f>& b);
double polygonIoU(const Quad& a, const Quad& b);

// The part of a polygon's convex hull that lies inside an image of `size` pixels, whose
// area is [-0.5, width - 0.5] x [-0.5, height - 0.5] (pixel centres at integers); empty
// when nothing of it does.
std::vector<cv::Point2f> clippedToImage(const std::vector<cv::Point2f>& polygon, cv::Size size);

}  // namespace parkloc::geometry
