#pragma once
// Stage 4a of the pipeline, the level vote: which level of the garage the vehicle drives on.
// Garages repeat their parking numbers on every level, so a text alone does not say where
// the vehicle is. Unless the level is given (PipelineOptions::level), every parking number
// and pillar text seen votes for each level the map has it on; a level with more votes than
// any other wins. parkloc votes while it does not track (and until a level is known); the
// paper's pipeline keeps its first winner for the drive.
#include <string>
#include <vector>

#include "localize/frame_types.h"
#include "map/hd_map.h"

namespace parkloc::localize {

class LevelVote {
 public:
  // `fixed`: the level given for the drive ("": voted).
  explicit LevelVote(std::string fixed = "") : fixed_(std::move(fixed)) {}
  void reset() { active_.clear(); }

  // The level driven on ("" while unknown: all levels).
  const std::string& current() const { return fixed_.empty() ? active_ : fixed_; }

  // `settled`: a level once won holds (the track holds it, or the paper's pipeline runs).
  void update(const std::vector<CameraResult>& cameras, const map::HdMap& map, bool settled);

 private:
  std::string fixed_;
  std::string active_;
};

}  // namespace parkloc::localize
