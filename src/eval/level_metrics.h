#pragma once
// How well a run knew the garage level: frame by frame the true level, whether a text that
// tells the level was legible in view (a level sign, or a text the map has on some levels
// only), and what the estimate said. Per stretch on one level: how long after the first such
// text the estimate decided on the right level (the first stretch: the decision; after a
// ramp: following the change).
#include <string>
#include <vector>

#include "io/labels.h"
#include "map/hd_map.h"

namespace parkloc::eval {

struct LevelFrame {
  double timestamp = 0.0;
  std::string truth;                  // the level driven on
  bool telling_text_in_view = false;  // a legible text that tells the level
  bool has_pose = false;
  std::string level;  // the estimate
  bool decided = false;
};

struct LevelScore {
  size_t frames = 0;
  size_t with_pose = 0;
  size_t decided = 0;
  size_t decided_right = 0;
  // Per stretch with a telling text in view: seconds from the first one to the first frame
  // decided on the right level; the first stretch of each drive and the later ones apart.
  std::vector<double> decision_delays_s;
  std::vector<double> change_delays_s;
  // Stretches with a telling text in view that ended before the right level was decided.
  size_t stretches_never_decided = 0;
  size_t changes = 0;  // level changes driven

  void add(const LevelScore& other);
  double rightWhereDecided() const;  // 1 when nothing was decided
};

// Whether the label's text tells the level on `map`: it names a level of the map, or the map
// has it on some of its levels only.
bool tellsLevel(const map::HdMap& map, const std::string& text);
// Whether any legible label of the frame set tells the level.
bool tellingTextInView(const map::HdMap& map, const std::vector<io::ImageLabels>& labels);

// One drive's frames, in time order.
LevelScore scoreLevels(const std::vector<LevelFrame>& frames);

}  // namespace parkloc::eval
