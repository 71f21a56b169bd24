#include "eval/map_comparison.h"

#include <algorithm>
#include <cmath>

#include "eval/ocr_metrics.h"

namespace parkloc::eval {

std::map<std::string, int> legibleFrameSets(const io::Sequence& drive) {
  std::map<std::string, int> frames;
  const OcrEvaluationOptions options;
  for (size_t f = 0; f < drive.timestamps().size(); ++f) {
    std::set<std::string> seen;
    for (const std::string& camera : drive.cameras()) {
      const auto labels = drive.loadLabels(f, camera);
      if (!labels) continue;
      for (const io::LabelInstance& l : labels->instances)
        if (caredFor(l, options) && !l.landmark_id.empty()) seen.insert(l.landmark_id);
    }
    for (const std::string& id : seen) ++frames[id];
  }
  return frames;
}

MapComparison compareMaps(const map::HdMap& built, const map::HdMap& truth,
                          const std::string& level,
                          const std::map<std::string, int>& legible_frames,
                          const MapComparisonOptions& options) {
  MapComparison out;
  out.level = level;
  if (out.level.empty()) {
    const auto levels = map::distinctLevels(built);
    if (levels.size() == 1) out.level = levels.front();
  }
  out.built = static_cast<int>(built.size());
  // Matches by text: a built landmark to the one true landmark of its text on the level.
  std::vector<std::pair<const map::Landmark*, const map::Landmark*>> matches;
  for (const map::Landmark& b : built.landmarks()) {
    const auto found = truth.findByText(b.text, out.level);
    if (found.size() == 1)
      matches.emplace_back(&b, found.front());
    else
      out.phantoms.push_back(b.text);
  }
  // The alignment starts from the pair of matches that most others agree with (every pair is
  // tried: a map has tens of texts): one landmark at a wrong place must not pull the first fit
  // so far that no landmark is within reach of its true place.
  const auto agreeingWith = [&](const geometry::PlanarFit& fit) {
    std::vector<bool> in(matches.size());
    for (size_t m = 0; m < matches.size(); ++m)
      in[m] = (fit.apply(matches[m].first->position.head<2>()) -
               matches[m].second->position.head<2>())
                  .norm() <= options.wrong_place_m;
    return in;
  };
  std::vector<bool> inlier(matches.size(), true);
  size_t most = 0;
  for (size_t i = 0; i < matches.size(); ++i)
    for (size_t j = i + 1; j < matches.size(); ++j) {
      const auto pair = geometry::fitPlanar(
          {matches[i].first->position.head<2>(), matches[j].first->position.head<2>()},
          {matches[i].second->position.head<2>(), matches[j].second->position.head<2>()},
          /*with_scale=*/false);
      if (!pair) continue;
      const std::vector<bool> in = agreeingWith(*pair);
      const auto count = static_cast<size_t>(std::count(in.begin(), in.end(), true));
      if (count > most) {
        most = count;
        inlier = in;
      }
    }
  for (int round = 0; round < 3; ++round) {
    std::vector<Eigen::Vector2d> from, to;
    for (size_t m = 0; m < matches.size(); ++m)
      if (inlier[m]) {
        from.push_back(matches[m].first->position.head<2>());
        to.push_back(matches[m].second->position.head<2>());
      }
    out.fit = geometry::fitPlanar(from, to, /*with_scale=*/false);
    if (!out.fit) break;
    const std::vector<bool> in = agreeingWith(*out.fit);
    if (in == inlier) break;
    inlier = in;
  }
  std::vector<double> position, heading, width, height;
  std::set<std::string> found_ids;
  for (size_t m = 0; m < matches.size(); ++m) {
    const map::Landmark& b = *matches[m].first;
    const map::Landmark& t = *matches[m].second;
    LandmarkError e;
    e.text = b.text;
    const Eigen::Vector2d p =
        out.fit ? out.fit->apply(b.position.head<2>()) : Eigen::Vector2d(b.position.head<2>());
    const double yaw = out.fit ? out.fit->to_from_from.yaw : 0.0;
    e.position_m = (p - t.position.head<2>()).norm();
    e.heading_deg = geometry::wrapAngle(b.heading + yaw - t.heading) * 180.0 / M_PI;
    e.width_rel = b.width / t.width - 1.0;
    e.height_rel = b.height / t.height - 1.0;
    e.wrong_place = e.position_m > options.wrong_place_m;
    out.errors.push_back(e);
    if (e.wrong_place) {
      out.phantoms.push_back(b.text);
      continue;
    }
    found_ids.insert(t.id);
    position.push_back(e.position_m);
    heading.push_back(std::fabs(e.heading_deg));
    width.push_back(std::fabs(e.width_rel));
    height.push_back(std::fabs(e.height_rel));
  }
  out.position_m = summarize(position);
  out.abs_heading_deg = summarize(heading);
  out.abs_width_rel = summarize(width);
  out.abs_height_rel = summarize(height);
  for (const map::Landmark& t : truth.landmarks()) {
    if (t.cls != map::TextClass::kParkingNumber || (!out.level.empty() && t.level != out.level))
      continue;
    ++out.true_parking_numbers;
    if (!legible_frames.empty()) {
      const auto it = legible_frames.find(t.id);
      if (it == legible_frames.end() || it->second < options.legible_frame_sets) continue;
    }
    ++out.legible;
    if (found_ids.count(t.id))
      ++out.legible_found;
    else
      out.missing.push_back(t.text);
  }
  out.completeness = out.legible > 0 ? static_cast<double>(out.legible_found) / out.legible : 0.0;
  return out;
}

}  // namespace parkloc::eval
