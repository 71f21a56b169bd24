#pragma once
// The floor views a spotter detects in, one per camera calibration, and where a detection's
// image lies in them: the whole floor view, or a mosaic of windows of a wider view around the
// texts the map places beyond it (ocr/placed_windows.h).
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <utility>
#include <vector>

#include "geometry/rig.h"
#include "ocr/ground_view.h"
#include "ocr/placed_windows.h"
#include "ocr/quad.h"

namespace parkloc::ocr {

// The image a floor detection ran on: `view` itself, or `mosaic`, windows of it.
struct FloorWindow {
  const GroundView* view = nullptr;
  const WindowMosaic* mosaic = nullptr;  // the image is this mosaic of `view`; null: `view`
  // Read only the boxes near a placed text, and keep only those that match one.
  bool only_placed_texts = false;

  // What to add to the image pixels of what lies at `p` to get `view` pixels; empty in a gap
  // between windows.
  std::optional<cv::Point2f> shiftAt(const cv::Point2f& p) const;
  // Whether a quad (reading order, shifted by `shift` into the view) may run out of what the
  // camera sees at its start and at its end: a point a quarter of its length beyond that end
  // is not in the image or lies behind the vehicle's body.
  std::pair<bool, bool> mayRunOutOfSight(const Quad& quad, const cv::Point2f& shift) const;
};

// Ground views built on first use for each camera calibration (their remap tables are costly),
// keyed by the whole calibration, not the name: two rigs may both have a "left" camera.
class FloorViews {
 public:
  // `reach` is the wider view of the windows beyond `view`; it takes `view`'s resolution, the
  // one the floor detector was tuned at.
  FloorViews(const GroundViewOptions& view, const GroundViewOptions& reach);

  const GroundView& view(const geometry::RigCamera& camera);
  const GroundView& reach(const geometry::RigCamera& camera);

 private:
  GroundViewOptions view_options_, reach_options_;
  std::vector<std::unique_ptr<GroundView>> views_, reaches_;
};

}  // namespace parkloc::ocr
