#include "localize/level_vote.h"

#include <map>
#include <set>

namespace parkloc::localize {

void LevelVote::update(const std::vector<CameraResult>& cameras, const map::HdMap& map,
                       bool settled) {
  if (!fixed_.empty() || (settled && !active_.empty())) return;
  std::map<std::string, int> votes;
  for (const auto& c : cameras) {
    for (const auto& t : c.instances) {
      if (t.cls != map::TextClass::kParkingNumber && t.cls != map::TextClass::kPillar) continue;
      std::set<std::string> levels;
      for (const auto* l : map.findByText(t.text)) levels.insert(l->level);
      for (const auto& level : levels) ++votes[level];
    }
  }
  int best = 0;
  bool tie = false;
  std::string winner;
  for (const auto& [level, n] : votes) {
    if (n > best) {
      best = n;
      winner = level;
      tie = false;
    } else if (n == best) {
      tie = true;
    }
  }
  if (best > 0 && !tie) active_ = winner;
}

}  // namespace parkloc::localize
