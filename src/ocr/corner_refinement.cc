#include "ocr/corner_refinement.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "geometry/ground_projection.h"

namespace parkloc::ocr {
namespace {

struct InkMask {
  cv::Mat mask;  // 8-bit, 255 where ink, crop coordinates
  cv::Mat image_from_crop;
};

// The crop's outer two pixels: background, as DB's box leaves a margin around the text.
cv::Mat borderMask(cv::Size size) {
  cv::Mat border(size, CV_8U, cv::Scalar(255));
  border(cv::Rect(2, 2, std::max(size.width - 4, 1), std::max(size.height - 4, 1))).setTo(0);
  return border;
}

// The median of an 8-bit channel's pixels under `mask`.
uchar medianUnder(const cv::Mat& channel, const cv::Mat& mask) {
  std::vector<uchar> v;
  for (int y = 0; y < channel.rows; ++y)
    for (int x = 0; x < channel.cols; ++x)
      if (mask.at<uchar>(y, x)) v.push_back(channel.at<uchar>(y, x));
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// The ink in `channel` (crop pixels, 8-bit): Otsu's split, `ink_is_bright` or the side the
// border is not on (DB's box leaves a margin of background around the text); nullopt when ink
// and background means differ by less than min_contrast.
std::optional<cv::Mat> splitInk(const cv::Mat& channel, std::optional<bool> ink_is_bright,
                                const CornerRefinementOptions& options) {
  cv::Mat binary;
  const double threshold =
      cv::threshold(channel, binary, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU);
  if (!ink_is_bright) ink_is_bright = cv::mean(channel, borderMask(channel.size()))[0] <= threshold;
  if (!*ink_is_bright) cv::bitwise_not(binary, binary);
  const double ink_mean = cv::mean(channel, binary)[0], bg_mean = cv::mean(channel, ~binary)[0];
  if (std::abs(ink_mean - bg_mean) < options.min_contrast) return std::nullopt;
  return binary;
}

// Numbers painted inside a frame or on a patch of colour: the ink's split may take the frame
// or the patch, whose box is the backing's, not the text's. A component at least as wide as
// it is high (a glyph is narrower) whose outline, holes filled, fills 9/10 of its minimum-area
// rectangle (glyph outlines are not rectangles), with holes of a tenth of it or more, is such a
// backing: a thin ring (under 0.45 of its filled area) is a frame, dropped for the glyphs
// inside it; a solid one is a patch, whose holes are the glyphs (with their counters).
cv::Mat glyphsInsideBackings(const cv::Mat& keep, const CornerRefinementOptions& options) {
  if (!options.frames && !options.patches) return keep;
  constexpr double kMinRectangleFill = 0.9, kMinHoleShare = 0.1, kRingShareMax = 0.45;
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(keep, labels, stats, centroids, 8, CV_32S);
  cv::Mat out = keep.clone();
  for (int i = 1; i < n; ++i) {
    const int cw = stats.at<int>(i, cv::CC_STAT_WIDTH), ch = stats.at<int>(i, cv::CC_STAT_HEIGHT);
    if (cw < ch) continue;
    const cv::Mat component = labels == i;
    std::vector<std::vector<cv::Point>> outer;
    cv::findContours(component, outer, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
    cv::Mat filled = cv::Mat::zeros(keep.size(), CV_8U);
    cv::drawContours(filled, outer, -1, cv::Scalar(255), cv::FILLED);
    const double filled_area = cv::countNonZero(filled);
    const double area = stats.at<int>(i, cv::CC_STAT_AREA);
    std::vector<cv::Point> points;
    for (const auto& c : outer) points.insert(points.end(), c.begin(), c.end());
    const cv::Size2f rect = cv::minAreaRect(points).size;
    if (filled_area < kMinRectangleFill * (rect.width + 1) * (rect.height + 1) ||
        filled_area - area < kMinHoleShare * filled_area)
      continue;
    const bool ring = area < kRingShareMax * filled_area;
    if (ring ? !options.frames : !options.patches) continue;
    out.setTo(0, component);
    if (!ring) out.setTo(255, filled & ~component);
  }
  return out;
}

// The components of `binary` that do not touch the crop's border (slot lines, neighbours, a
// car's shadow), backings replaced by the glyphs on them, or nullopt when they leave too little
// to be a text.
std::optional<cv::Mat> innerComponents(const cv::Mat& binary,
                                       const CornerRefinementOptions& options) {
  const int h = binary.rows, w = binary.cols;
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(binary, labels, stats, centroids, 8, CV_32S);
  cv::Mat keep = cv::Mat::zeros(h, w, CV_8U);
  int kept_area = 0;
  for (int i = 1; i < n; ++i) {
    const int x = stats.at<int>(i, cv::CC_STAT_LEFT), y = stats.at<int>(i, cv::CC_STAT_TOP);
    const int cw = stats.at<int>(i, cv::CC_STAT_WIDTH), ch = stats.at<int>(i, cv::CC_STAT_HEIGHT);
    const int area = stats.at<int>(i, cv::CC_STAT_AREA);
    const bool touches = x <= 0 || y <= 0 || x + cw >= w || y + ch >= h;
    if (touches || area < h * h / 400) continue;
    keep.setTo(255, labels == i);
    kept_area += area;
  }
  if (kept_area < h * h / 20) return std::nullopt;
  keep = glyphsInsideBackings(keep, options);
  if (cv::countNonZero(keep) < h * h / 20) return std::nullopt;
  return keep;
}

// How far each pixel's chroma lies from the floor's: the median colour of the crop's border
// (distance in CIE Lab's a* b*, 8-bit). Yellow paint on grey concrete differs from it in
// colour more than in brightness, and the colourless dark of a car's bumper or shadow at the
// crop's edge, which takes a grey-level split for itself and leaves the paint with the floor,
// stays with the floor here.
cv::Mat colourDistance(const cv::Mat& crop, double sigma) {
  buildColourTables();
  cv::Mat lab;
  cv::cvtColor(crop, lab, cv::COLOR_BGR2Lab);
  std::vector<cv::Mat> channels;
  cv::split(lab, channels);
  const cv::Mat border = borderMask(crop.size());
  cv::Mat from_floor[2];  // a*, b* less the floor's
  for (int c = 0; c < 2; ++c) {
    cv::Mat& channel = channels[static_cast<size_t>(c + 1)];
    if (sigma >= 0.3) cv::GaussianBlur(channel, channel, {0, 0}, sigma);
    channel.convertTo(from_floor[c], CV_32F, 1.0, -medianUnder(channel, border));
  }
  cv::Mat distance, out;
  cv::magnitude(from_floor[0], from_floor[1], distance);
  distance.convertTo(out, CV_8U);
  return out;
}

std::optional<InkMask> inkMask(const cv::Mat& image, const Quad& detected,
                               const CornerRefinementOptions& options) {
  const Quad quad = expandQuad(detected, options.search_expand_x, options.search_expand_y);
  const int h = options.crop_height;
  const int w = std::clamp(
      static_cast<int>(std::lround(quadWidth(quad) / std::max(quadHeight(quad), 1.f) * h)), 8,
      16 * h);
  const cv::Mat crop_from_image = rectifyingHomography(quad, w, h);
  cv::Mat crop, gray;
  cv::warpPerspective(image, crop, crop_from_image, {w, h}, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  cv::cvtColor(crop, gray, cv::COLOR_BGR2GRAY);
  const double crop_px_per_raw_px = h / std::max(quadHeight(quad), 1.f);
  const double sigma = options.denoise_sigma_raw_px * crop_px_per_raw_px;
  if (sigma >= 0.3) cv::GaussianBlur(gray, gray, {0, 0}, sigma);
  // Grey levels first; where they find no text, the distance from the floor's colour.
  if (const auto binary = splitInk(gray, std::nullopt, options))
    if (auto keep = innerComponents(*binary, options)) return InkMask{*keep, crop_from_image.inv()};
  if (!options.colour_fallback) return std::nullopt;
  if (const auto binary = splitInk(colourDistance(crop, sigma), true, options))
    if (auto keep = innerComponents(*binary, options)) return InkMask{*keep, crop_from_image.inv()};
  return std::nullopt;
}

}  // namespace

void buildColourTables() {
  // OpenCV builds the tables without a lock: two threads converting at once would both build
  // them and one copy is lost. A function-local static is initialised once, the other threads
  // waiting for it.
  static const bool built = [] {
    cv::Mat lab;
    cv::cvtColor(cv::Mat(1, 1, CV_8UC3, cv::Scalar::all(128)), lab, cv::COLOR_BGR2Lab);
    return true;
  }();
  (void)built;
}

std::vector<cv::Point2f> inkOutline(const cv::Mat& image, const Quad& quad,
                                    const CornerRefinementOptions& options) {
  const auto ink = inkMask(image, quad, options);
  if (!ink) return {};
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(ink->mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
  std::vector<cv::Point2f> points;
  for (const auto& c : contours)
    for (const auto& p : c) points.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y));
  if (points.empty()) return {};
  std::vector<cv::Point2f> in_image;
  cv::perspectiveTransform(points, in_image, ink->image_from_crop);
  return in_image;
}

std::optional<Quad> refineInCrop(const cv::Mat& image, const Quad& quad,
                                 const CornerRefinementOptions& options) {
  const auto ink = inkMask(image, quad, options);
  if (!ink) return std::nullopt;
  const cv::Rect box = cv::boundingRect(ink->mask);
  // Outer pixel edges of the ink box.
  const float x0 = box.x - 0.5f, y0 = box.y - 0.5f;
  const float x1 = box.x + box.width - 0.5f, y1 = box.y + box.height - 0.5f;
  return transformQuad({cv::Point2f(x0, y0), {x1, y0}, {x1, y1}, {x0, y1}}, ink->image_from_crop);
}

std::optional<Quad> refineOnGround(const cv::Mat& image, const Quad& quad,
                                   const geometry::RigCamera& camera,
                                   const CornerRefinementOptions& options) {
  const auto outline = inkOutline(image, quad, options);
  if (outline.size() < 4) return std::nullopt;
  const auto ground = geometry::Plane::ground();
  auto toGround = [&](const cv::Point2f& p) -> std::optional<cv::Point2f> {
    const auto g = geometry::pixelToPlane(camera, {p.x, p.y}, ground);
    if (!g) return std::nullopt;
    return cv::Point2f(static_cast<float>(g->x()), static_cast<float>(g->y()));
  };
  std::vector<cv::Point2f> on_ground;
  for (const auto& p : outline) {
    const auto g = toGround(p);
    if (!g) return std::nullopt;
    on_ground.push_back(*g);
  }
  const cv::RotatedRect rect = cv::minAreaRect(on_ground);
  const double long_side = std::max(rect.size.width, rect.size.height);
  const double short_side = std::min(rect.size.width, rect.size.height);
  if (short_side > options.max_ground_height || long_side > options.max_ground_width)
    return std::nullopt;

  // Reading direction and "up" on the ground from the image quad's edges.
  const auto left = toGround((quad[0] + quad[3]) * 0.5f),
             right = toGround((quad[1] + quad[2]) * 0.5f);
  const auto top = toGround((quad[0] + quad[1]) * 0.5f),
             bottom = toGround((quad[2] + quad[3]) * 0.5f);
  if (!left || !right || !top || !bottom) return std::nullopt;
  cv::Point2f along = *right - *left, up = *top - *bottom;
  cv::Point2f axes[2];
  const double a = rect.angle * CV_PI / 180.0;
  axes[0] = {static_cast<float>(std::cos(a)), static_cast<float>(std::sin(a))};
  axes[1] = {-axes[0].y, axes[0].x};
  float half[2] = {rect.size.width * 0.5f, rect.size.height * 0.5f};
  // The rectangle axis closer to the image's reading direction is the reading axis.
  const int r = std::abs(axes[0].dot(along)) >= std::abs(axes[1].dot(along)) ? 0 : 1;
  cv::Point2f u = axes[r] * (axes[r].dot(along) >= 0 ? 1.f : -1.f);
  cv::Point2f v = axes[1 - r] * (axes[1 - r].dot(up) >= 0 ? 1.f : -1.f);
  const float hw = half[r], hh = half[1 - r];
  const cv::Point2f c = rect.center;
  const cv::Point2f corners[4] = {c - u * hw + v * hh, c + u * hw + v * hh, c + u * hw - v * hh,
                                  c - u * hw - v * hh};
  const geometry::Rigid3 camera_from_vehicle = camera.vehicle_from_camera.inverse();
  Quad out;
  for (int k = 0; k < 4; ++k) {
    const auto px = camera.model.project(camera_from_vehicle *
                                         Eigen::Vector3d(corners[k].x, corners[k].y, 0.0));
    if (!px) return std::nullopt;
    out[k] = cv::Point2f(static_cast<float>(px->x()), static_cast<float>(px->y()));
  }
  return out;
}

bool plausibleRefinement(const Quad& detected, const Quad& refined,
                         const CornerRefinementOptions& options) {
  if (quadWidth(refined) < options.min_length_share * quadWidth(detected)) return false;
  const Quad limit = expandQuad(detected, 1.3f, 1.5f);
  const std::vector<cv::Point2f> hull(limit.begin(), limit.end());
  for (const auto& p : refined)
    if (cv::pointPolygonTest(hull, p, false) < 0) return false;
  return true;
}

}  // namespace parkloc::ocr
