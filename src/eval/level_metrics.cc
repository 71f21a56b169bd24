#include "eval/level_metrics.h"

#include <optional>
#include <set>

#include "localize/level_estimate.h"

namespace parkloc::eval {
void LevelScore::add(const LevelScore& o) {
  frames += o.frames;
  with_pose += o.with_pose;
  decided += o.decided;
  decided_right += o.decided_right;
  decision_delays_s.insert(decision_delays_s.end(), o.decision_delays_s.begin(),
                           o.decision_delays_s.end());
  change_delays_s.insert(change_delays_s.end(), o.change_delays_s.begin(), o.change_delays_s.end());
  stretches_never_decided += o.stretches_never_decided;
  changes += o.changes;
}

double LevelScore::rightWhereDecided() const {
  return decided == 0 ? 1.0 : static_cast<double>(decided_right) / static_cast<double>(decided);
}

namespace {

// tellsLevel with the map's levels at hand.
bool tellsLevelOf(const map::HdMap& map, const std::vector<std::string>& levels,
                  const std::string& text) {
  if (levels.size() < 2) return false;
  if (localize::levelNamedBy(levels, text)) return true;
  const size_t with_text = map::levelsWithText(map, text).size();
  return with_text > 0 && with_text < levels.size();
}

}  // namespace

bool tellsLevel(const map::HdMap& map, const std::string& text) {
  return tellsLevelOf(map, map::distinctLevels(map), text);
}

bool tellingTextInView(const map::HdMap& map, const std::vector<io::ImageLabels>& labels) {
  const std::vector<std::string> levels = map::distinctLevels(map);
  for (const io::ImageLabels& image : labels)
    for (const io::LabelInstance& l : image.instances)
      if (l.legible && l.occluded_fraction < 0.5 && tellsLevelOf(map, levels, l.text)) return true;
  return false;
}

LevelScore scoreLevels(const std::vector<LevelFrame>& frames) {
  LevelScore s;
  size_t begin = 0;
  bool first_stretch = true;
  while (begin < frames.size()) {
    size_t end = begin;
    while (end < frames.size() && frames[end].truth == frames[begin].truth) ++end;
    // The stretch [begin, end) on one level.
    std::optional<double> seen, decided;
    for (size_t i = begin; i < end; ++i) {
      const LevelFrame& f = frames[i];
      ++s.frames;
      s.with_pose += f.has_pose;
      if (f.decided) {
        ++s.decided;
        s.decided_right += f.level == f.truth;
      }
      if (f.telling_text_in_view && !seen) seen = f.timestamp;
      if (seen && !decided && f.decided && f.level == f.truth) decided = f.timestamp;
    }
    if (!first_stretch) ++s.changes;
    if (seen) {
      if (decided)
        (first_stretch ? s.decision_delays_s : s.change_delays_s).push_back(*decided - *seen);
      else
        ++s.stretches_never_decided;
    }
    first_stretch = false;
    begin = end;
  }
  return s;
}

}  // namespace parkloc::eval
