#include "ocr/placed_windows.h"

#include <algorithm>
#include <cmath>

namespace parkloc::ocr {
namespace {

// `window` grown to sides that are multiples of 32 about its centre, shifted back inside
// `bounds` where it sticks out (and cut to it where `bounds` is smaller).
cv::Rect strideAligned(const cv::Rect& window, const cv::Rect& bounds) {
  auto up32 = [](int v) { return std::max(32, (v + 31) / 32 * 32); };
  const int w = std::min(up32(window.width), bounds.width);
  const int h = std::min(up32(window.height), bounds.height);
  int x = window.x + window.width / 2 - w / 2, y = window.y + window.height / 2 - h / 2;
  x = std::clamp(x, bounds.x, bounds.x + bounds.width - w);
  y = std::clamp(y, bounds.y, bounds.y + bounds.height - h);
  return {x, y, w, h};
}

}  // namespace

double apparentHeightPx(const GroundView& view, const map::PlacedText& text, double height_m) {
  const Eigen::Vector2d across = Eigen::Vector2d(-text.reading.y(), text.reading.x()).normalized();
  const auto top = view.rawFromView(view.viewFromGround(text.vehicle_xy + across * height_m / 2));
  const auto bottom =
      view.rawFromView(view.viewFromGround(text.vehicle_xy - across * height_m / 2));
  return top && bottom ? cv::norm(*top - *bottom) : 0.0;
}

std::vector<cv::Rect> windowsBeyondView(const GroundView& view, const GroundView& reach,
                                        const std::vector<map::PlacedText>& placed,
                                        const PlacedWindowOptions& options) {
  const double resolution = reach.options().resolution;
  const int inside_px = static_cast<int>(std::lround(options.inside_margin_m / resolution));
  const int side_px = static_cast<int>(std::lround(options.side_m / resolution));
  cv::Rect covered = view.rect();
  covered.x += inside_px;
  covered.y += inside_px;
  covered.width -= 2 * inside_px;
  covered.height -= 2 * inside_px;

  std::vector<std::pair<double, cv::Rect>> candidates;  // apparent height, window
  for (const auto& text : placed) {
    const cv::Point2f in_view = view.viewFromGround(text.vehicle_xy);
    if (covered.width > 0 && covered.height > 0 && covered.contains(in_view)) continue;
    const cv::Point2f centre = reach.viewFromGround(text.vehicle_xy);
    if (!reach.rect().contains(centre) || !reach.seesTheFloorAt(centre)) continue;
    const double height = apparentHeightPx(reach, text, options.text_height_m);
    if (height < options.min_height_px) continue;
    candidates.emplace_back(
        height, cv::Rect(static_cast<int>(std::lround(centre.x)) - side_px / 2,
                         static_cast<int>(std::lround(centre.y)) - side_px / 2, side_px, side_px));
  }
  // The tallest first: they are the likeliest to be found.
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  if (options.max_texts > 0 && candidates.size() > static_cast<size_t>(options.max_texts))
    candidates.resize(static_cast<size_t>(options.max_texts));
  std::vector<cv::Rect> windows;
  for (const auto& [height, window] : candidates) windows.push_back(window);
  // Overlapping windows become their bounding box, until none overlap: a text is detected
  // once, in one window.
  for (bool merged = true; merged;) {
    merged = false;
    for (size_t i = 0; i < windows.size() && !merged; ++i)
      for (size_t j = i + 1; j < windows.size() && !merged; ++j)
        if ((windows[i] & windows[j]).area() > 0) {
          windows[i] |= windows[j];
          windows.erase(windows.begin() + static_cast<std::ptrdiff_t>(j));
          merged = true;
        }
  }
  for (auto& w : windows) w = strideAligned(w & reach.rect(), reach.rect());
  return windows;
}

WindowMosaic mosaicOf(const GroundView& view, const cv::Mat& raw,
                      const std::vector<cv::Rect>& windows, int gap_px) {
  WindowMosaic mosaic;
  int width = 0, height = 0;
  for (const cv::Rect& w : windows) {
    mosaic.tiles.emplace_back(width, 0, w.width, w.height);
    mosaic.shifts.emplace_back(static_cast<float>(w.x - width), static_cast<float>(w.y));
    width += w.width + gap_px;
    height = std::max(height, w.height);
  }
  if (windows.empty()) return mosaic;
  mosaic.image = cv::Mat(height, width - gap_px, raw.type(), cv::Scalar::all(0));
  for (size_t i = 0; i < windows.size(); ++i) {
    const cv::Mat rendered = view.render(raw, windows[i]);
    rendered.copyTo(mosaic.image(cv::Rect(mosaic.tiles[i].tl(), rendered.size())));
  }
  return mosaic;
}

std::optional<cv::Point2f> WindowMosaic::shiftAt(const cv::Point2f& p) const {
  for (size_t i = 0; i < tiles.size(); ++i) {
    const cv::Rect& t = tiles[i];
    if (p.x >= t.x && p.x < t.x + t.width && p.y >= t.y && p.y < t.y + t.height) return shifts[i];
  }
  return std::nullopt;
}

}  // namespace parkloc::ocr
