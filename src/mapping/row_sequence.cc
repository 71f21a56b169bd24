#include "mapping/row_sequence.h"

#include <cmath>

#include "map/numbering.h"

namespace parkloc::mapping {

RowSequence::RowSequence(const std::vector<PlacedNumber>& landmarks,
                         const RowSequenceOptions& options)
    : options_(options) {
  for (const PlacedNumber& a : landmarks)
    for (const PlacedNumber& b : landmarks) {
      const auto step = map::numberStep(a.text, b.text);
      const Eigen::Vector2d d = b.place - a.place;
      if (!step || *step != 1 || d.norm() > options_.max_segment_m || d.norm() < 1e-6) continue;
      segments_.push_back({a, b, d.normalized()});
    }
}

bool RowSequence::onRow(const Segment& s, const Eigen::Vector2d& place, const PlacedNumber** from,
                        double* along) const {
  const double to_low = (place - s.low.place).norm();
  const double to_high = (place - s.high.place).norm();
  *from = to_low <= to_high ? &s.low : &s.high;
  const Eigen::Vector2d d = place - (*from)->place;
  *along = d.dot(s.along);
  const double lateral = std::abs(d.x() * s.along.y() - d.y() * s.along.x());
  return lateral <= options_.lateral_m && std::abs(*along) <= options_.reach_m;
}

bool RowSequence::allows(const std::string& text, const Eigen::Vector2d& place) const {
  for (const Segment& s : segments_) {
    const PlacedNumber* from = nullptr;
    double along = 0.0;
    if (!onRow(s, place, &from, &along)) continue;
    const auto step = map::numberStep(from->text, text);
    if (!step || *step == 0) continue;
    // Numbers grow along `along`: the bays between, as few as the widest bays and as many as
    // the narrowest fit into the distance, give or take the places' error.
    const double apart = std::abs(along);
    const auto fewest = std::max(
        1LL,
        static_cast<long long>(std::ceil((apart - options_.place_error_m) / options_.max_pitch_m)));
    const auto most =
        static_cast<long long>(std::floor((apart + options_.place_error_m) / options_.min_pitch_m));
    const long long signed_bays = along >= 0.0 ? *step : -*step;
    if (signed_bays >= fewest && signed_bays <= most) return true;
  }
  return false;
}

}  // namespace parkloc::mapping
