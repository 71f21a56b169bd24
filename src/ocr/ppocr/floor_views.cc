#include "ocr/ppocr/floor_views.h"

namespace parkloc::ocr {

namespace {

// How far beyond a box's end mayRunOutOfSight looks, as a fraction of the box's length: a
// number cut by the border or the body has its missing characters there.
constexpr float kBeyondTheEnd = 0.25f;

const GroundView& viewFor(std::vector<std::unique_ptr<GroundView>>& views,
                          const geometry::RigCamera& camera, const GroundViewOptions& options) {
  for (const auto& view : views)
    if (geometry::sameCalibration(view->camera(), camera)) return *view;
  views.push_back(std::make_unique<GroundView>(camera, options));
  return *views.back();
}

}  // namespace

std::optional<cv::Point2f> FloorWindow::shiftAt(const cv::Point2f& p) const {
  return mosaic != nullptr ? mosaic->shiftAt(p) : cv::Point2f(0.f, 0.f);
}

std::pair<bool, bool> FloorWindow::mayRunOutOfSight(const Quad& quad,
                                                    const cv::Point2f& shift) const {
  const cv::Point2f start = 0.5f * (quad[0] + quad[3]), end = 0.5f * (quad[1] + quad[2]);
  const cv::Point2f beyond = kBeyondTheEnd * (end - start);
  return {!view->seesTheFloorAt(start - beyond + shift),
          !view->seesTheFloorAt(end + beyond + shift)};
}

FloorViews::FloorViews(const GroundViewOptions& view, const GroundViewOptions& reach)
    : view_options_(view), reach_options_(reach) {
  reach_options_.resolution = view.resolution;
}

const GroundView& FloorViews::view(const geometry::RigCamera& camera) {
  return viewFor(views_, camera, view_options_);
}

const GroundView& FloorViews::reach(const geometry::RigCamera& camera) {
  return viewFor(reaches_, camera, reach_options_);
}

}  // namespace parkloc::ocr
