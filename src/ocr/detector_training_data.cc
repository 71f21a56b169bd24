#include "ocr/detector_training_data.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <opencv2/imgproc.hpp>
#include <optional>

#include "common/error.h"
#include "io/polygon_points.h"
#include "io/sequence.h"
#include "io/sequence_conditions.h"
#include "ocr/quad.h"
#include "ocr/training_data_files.h"
#include "ocr/visible_part.h"

namespace parkloc::ocr {
namespace {

namespace fs = std::filesystem;

struct ViewText {
  std::array<cv::Point2f, 4> corners;
  bool care = false;
  map::TextClass cls = map::TextClass::kParkingNumber;
  std::string text;
};

bool insideView(const cv::Point2f& p, const cv::Size& size) {
  return p.x >= 0.f && p.y >= 0.f && p.x <= size.width - 1.f && p.y <= size.height - 1.f;
}

bool overlapsView(const std::array<cv::Point2f, 4>& corners, const cv::Size& size) {
  std::vector<cv::Point2f> hull;
  cv::convexHull(std::vector<cv::Point2f>(corners.begin(), corners.end()), hull);
  if (hull.size() < 3) return false;
  const float w = size.width - 1.f, h = size.height - 1.f;
  const std::vector<cv::Point2f> view = {{0.f, 0.f}, {w, 0.f}, {w, h}, {0.f, h}};
  std::vector<cv::Point2f> common;
  return cv::intersectConvexConvex(hull, view, common, true) > 0.f;
}

bool whollyInside(const std::array<cv::Point2f, 4>& corners, const cv::Size& size) {
  return std::all_of(corners.begin(), corners.end(),
                     [&](const cv::Point2f& p) { return insideView(p, size); });
}

// Text a reader could read where it is seen: legible and not hidden too much.
bool readable(const io::LabelInstance& inst, const DetectorDataOptions& options) {
  return inst.legible && inst.occluded_fraction < options.max_occluded_fraction;
}

// Care for the loss: text a reader could read, wholly in the image the detector sees.
bool careFor(const io::LabelInstance& inst, bool wholly_inside,
             const DetectorDataOptions& options) {
  return readable(inst, options) && !inst.truncated && wholly_inside;
}

// Floor text cut by the raw image's edge (black in the view) or by the view's own: the part
// the view shows is care when it keeps enough of the text to be worth boxing, else the whole
// text is a don't-care region. The evaluation matches such text by its part inside the image.
void keepSeenPart(const GroundView& view, const cv::Size& raw_size, const io::LabelInstance& inst,
                  const DetectorDataOptions& options, ViewText& t) {
  const auto seen = [&](const cv::Point2f& p) {
    if (!insideView(p, view.size())) return false;
    const auto raw = view.rawFromView(p);
    return raw && insideView(*raw, raw_size);
  };
  auto part = visiblePart(t.corners, seen);
  t.care = part && part->length_fraction >= options.min_seen_length &&
           part->height_fraction >= options.min_seen_height && readable(inst, options);
  if (!t.care) return;
  // The span runs over whole grid cells, which may end a little beyond the view's edge.
  const cv::Size size = view.size();
  for (auto& c : part->quad)
    c = {std::clamp(c.x, 0.f, size.width - 1.f), std::clamp(c.y, 0.f, size.height - 1.f)};
  t.corners = part->quad;
}

// The label's class and text; commas become spaces (the label line is comma separated).
void copyClassAndText(const io::LabelInstance& inst, ViewText& t) {
  t.cls = inst.cls;
  t.text = inst.text;
  std::replace(t.text.begin(), t.text.end(), ',', ' ');
}

// The labelled instances of one raw image in view pixels. The label polygons are the exact
// projections of the text corners, so casting them onto the floor places floor text exactly;
// text on pillars and plates lands farther out (and nowhere above the horizon), so it is kept
// only as a don't-care region, and only when that region is wholly in the view.
std::vector<ViewText> viewTexts(const GroundView& view, const cv::Size& raw_size,
                                const io::ImageLabels& labels, const map::HdMap& map,
                                const DetectorDataOptions& options) {
  std::vector<ViewText> out;
  for (const auto& inst : labels.instances) {
    ViewText t;
    const std::optional<Quad> corners = view.viewFromRaw(io::pointQuad(inst.polygon));
    if (!corners) continue;
    t.corners = *corners;
    const bool all_inside = whollyInside(t.corners, view.size());
    // Licence plates are not in the map; like pillar text they stand upright.
    const map::Landmark* landmark = map.findById(inst.landmark_id);
    const bool floor = landmark && landmark->surface == map::Surface::kGround;
    if (floor) {
      if (!overlapsView(t.corners, view.size())) continue;
      // A truncated instance runs off the raw image, i.e. into the black part of the view.
      if (all_inside && !inst.truncated)
        t.care = readable(inst, options);
      else
        keepSeenPart(view, raw_size, inst, options, t);
    } else if (!all_inside) {
      continue;
    }
    copyClassAndText(inst, t);
    out.push_back(std::move(t));
  }
  return out;
}

// The labelled instances of one raw image inside its horizon band, in band pixels.
std::vector<ViewText> bandTexts(const cv::Rect& band, const io::ImageLabels& labels,
                                const DetectorDataOptions& options) {
  const cv::Size size = band.size();
  const cv::Point2f offset(0.f, static_cast<float>(band.y));
  std::vector<ViewText> out;
  for (const auto& inst : labels.instances) {
    ViewText t;
    const Quad raw = io::pointQuad(inst.polygon);
    for (int k = 0; k < 4; ++k) t.corners[k] = raw[k] - offset;
    if (!overlapsView(t.corners, size)) continue;
    t.care = careFor(inst, whollyInside(t.corners, size), options);
    copyClassAndText(inst, t);
    out.push_back(std::move(t));
  }
  return out;
}

// The sequence's conditions joined by '+' ("blur+bright"); "none" when it names none.
std::string conditionOf(const io::Sequence& sequence) {
  const auto names = io::sequenceConditions(sequence.metaJson(), sequence.dir() + "/meta.json");
  if (names.empty()) return "none";
  std::string joined;
  for (const auto& n : names) joined += (joined.empty() ? "" : "+") + n;
  return joined;
}

void writeViewTexts(const fs::path& path, const std::vector<ViewText>& texts) {
  std::ofstream out(path);
  for (const auto& t : texts) {
    for (const auto& c : t.corners) out << fmt::format("{:.1f},{:.1f},", c.x, c.y);
    out << (t.care ? 1 : 0) << ',' << static_cast<int>(t.cls) << ',' << t.text << '\n';
  }
  if (!out) throw IoError(path.string() + ": cannot write");
}

// Options come from the command line; a tiny resolution would ask for gigabytes of view.
void checkViewOptions(const GroundViewOptions& v) {
  auto bad = [](const std::string& field, double value, const std::string& why) {
    return InputError(fmt::format("ground view option '{}' = {}: {}", field, value, why));
  };
  if (!(v.resolution > 0.0)) throw bad("resolution", v.resolution, "must be positive");
  if (!(v.far > v.near)) throw bad("far", v.far, "must exceed near");
  if (!(v.half_width > 0.0)) throw bad("half_width", v.half_width, "must be positive");
  // The view's side is at most the extent along and across the heading together.
  const double side_px = (v.far - v.near + 2.0 * v.half_width) / v.resolution;
  if (!(side_px <= 8192.0))
    throw bad("resolution", v.resolution, fmt::format("view up to {:.0f} px wide", side_px));
}

}  // namespace

DetectorDataStats writeDetectorTrainingData(const std::vector<std::string>& sequence_dirs,
                                            const DetectorDataOptions& options) {
  if (options.out_dir.empty()) throw InputError("detector data: no output folder given");
  const bool band = options.source == DetectorSource::kRawBand;
  if (band)
    checkBand(options.band);
  else
    checkViewOptions(options.view);
  const fs::path root(options.out_dir);
  createDirectory(root / "images");
  createDirectory(root / "labels");
  const fs::path index_path = root / "index.txt";
  std::ofstream index(index_path);
  if (!index) throw IoError(index_path.string() + ": cannot write");

  DetectorDataStats stats;
  for (size_t s = 0; s < sequence_dirs.size(); ++s) {
    const io::Sequence sequence(sequence_dirs[s]);
    const std::string name = sequenceName(sequence.dir());
    const std::string condition = conditionOf(sequence);
    std::vector<std::pair<std::string, std::optional<GroundView>>> views;
    for (const auto& camera : sequence.cameras())
      if (const auto* rig_camera = sequence.rig().find(camera))
        views.emplace_back(
            camera,
            band ? std::nullopt : std::optional<GroundView>(GroundView(*rig_camera, options.view)));
    for (const size_t f :
         sampledFrames(sequence, options.frame_stride, options.max_frames_per_sequence)) {
      for (const auto& [camera, view] : views) {
        const auto labels = sequence.loadLabels(f, camera);
        if (!labels) continue;  // nothing to learn from an unlabelled image
        const cv::Mat raw = loadBgrImage(sequence, f, camera);
        if (raw.empty()) continue;
        const std::string stem =
            fmt::format("{}_{}_{}", name, camera, io::timestampStem(sequence.timestamps()[f]));
        const std::string image_rel = "images/" + stem + ".png";
        const std::string labels_rel = "labels/" + stem + ".txt";
        std::vector<ViewText> texts;
        if (view) {
          texts = viewTexts(*view, raw.size(), *labels, sequence.map(), options);
          writeImage(root / image_rel, view->render(raw));
        } else {
          const auto* rig_camera = sequence.rig().find(camera);
          if (raw.cols != rig_camera->model.width || raw.rows != rig_camera->model.height)
            throw InputError(fmt::format("{} camera '{}': image {}x{} differs from its "
                                         "calibration's {}x{}",
                                         sequence.dir(), camera, raw.cols, raw.rows,
                                         rig_camera->model.width, rig_camera->model.height));
          const cv::Rect rows = bandRect(options.band, rig_camera->model);
          texts = bandTexts(rows, *labels, options);
          writeImage(root / image_rel, raw(rows));
        }
        writeViewTexts(root / labels_rel, texts);
        index << image_rel << ' ' << labels_rel << ' ' << condition << '\n';
        ++stats.images;
        for (const auto& t : texts) ++(t.care ? stats.care_instances : stats.dont_care_instances);
      }
    }
    if (options.progress) options.progress(s + 1, sequence_dirs.size());
  }
  index.flush();
  if (!index) throw IoError(index_path.string() + ": cannot write");
  return stats;
}

}  // namespace parkloc::ocr
