#pragma once
// The numbering along a row of bays, as the landmarks already decided show it. Bays are
// numbered in sequence along a row, one number per bay, and a bay with a pillar beside it is
// a little wider: two decided landmarks of consecutive numbers a few metres apart give the
// row's line and the direction its numbers grow in, and a place on that line, s metres from
// the nearer of the two, holds a number between s / max_pitch_m and s / min_pitch_m bays on
// (s give or take a place's error).
// It lets the consensus decide a place whose readings compete (a worn 7 read as 2 as often as
// 7) and which of two landmarks side by side out of sequence is the misread.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace parkloc::mapping {

struct RowSequenceOptions {
  // Two landmarks of consecutive numbers this close make a row segment: one or two bays.
  double max_segment_m = 4.0;
  // The width of one bay along the row, pillars included: parking numbers are 2.3 m or more
  // apart, and a bay beside a pillar is up to about a metre wider.
  double min_pitch_m = 2.3;
  double max_pitch_m = 3.3;
  // How far a place may lie from where its sightings put it, along the row.
  double place_error_m = 0.5;
  // A place is on a segment's row when it lies this close to its line (a place's radius) and
  // no farther along it than reach_m from the nearer landmark: beyond, the bays between are
  // counted too loosely.
  double lateral_m = 1.0;
  double reach_m = 20.0;
};

// A decided landmark: its reading and its place in the map being built.
struct PlacedNumber {
  std::string text;
  Eigen::Vector2d place = Eigen::Vector2d::Zero();
};

class RowSequence {
 public:
  RowSequence(const std::vector<PlacedNumber>& landmarks, const RowSequenceOptions& options);

  // Whether some row segment holds `place` and allows `text` there.
  bool allows(const std::string& text, const Eigen::Vector2d& place) const;

  size_t segments() const { return segments_.size(); }

 private:
  struct Segment {
    PlacedNumber low, high;  // the high number comes one after the low one
    Eigen::Vector2d along = Eigen::Vector2d::UnitX();  // unit, from low to high
  };
  // The segment's nearer landmark to `place`, and the signed distance along the row from it;
  // false when `place` is off the segment's row.
  bool onRow(const Segment& s, const Eigen::Vector2d& place, const PlacedNumber** from,
             double* along) const;

  RowSequenceOptions options_;
  std::vector<Segment> segments_;
};

}  // namespace parkloc::mapping
