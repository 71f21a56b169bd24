#pragma once
// The video-stream anomaly filter of the paper (OCR-RTPS section 3.3, Algorithm 1): a
// first-in-first-out queue of recently accepted parking numbers; a new number is kept only
// inside [median - k IQR, median + k IQR] of the queue (a box plot), and kept numbers enter
// the queue. Until the queue is full every number is kept ("keep inputting incoming numbers
// until it is full").
#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace parkloc::localize {

// Quartiles by linear interpolation between order statistics (Hyndman & Fan type 7, the
// default of numpy.percentile and R's quantile): the p-quantile of sorted x[0..n-1] lies at
// position p (n - 1).
struct Quartiles {
  double lower = 0.0;   // 25 %
  double median = 0.0;  // 50 %
  double upper = 0.0;   // 75 %
  double iqr() const { return upper - lower; }
};
// Empty for an empty sample.
std::optional<Quartiles> computeQuartiles(std::vector<double> values);

// The numeric part of a parking-number text: the last run of digits ("B2-117" -> 117,
// "098" -> 98). Empty when the text has no digit or the run is too long for an int.
std::optional<int> parkingNumberValue(const std::string& text);

struct BoxPlotFilterOptions {
  size_t queue_length = 30;  // the paper's 30 frames
  double iqr_factor = 1.5;   // the paper's 1.5 IQR
  // After this many rejections in a row the queue is cleared and refilled (0 = never, the
  // paper's literal rule). Without it a queue that holds one number 30 times (IQR 0) would
  // reject every other number forever; the paper expects the filter to "re-validate within
  // 3 seconds" after a turn, which needs some such escape.
  size_t reset_after_rejections = 0;
};

class BoxPlotFilter {
 public:
  explicit BoxPlotFilter(BoxPlotFilterOptions options = {}) : options_(options) {}

  // Algorithm 1 for one number: true = kept (and pushed into the queue).
  bool accept(double number);
  // Pushes a number vouched for by other means (a landmark accepted by the pose gate while
  // tracking), so that the queue follows the numbers around the vehicle.
  void remember(double number);
  // The range a number must fall into; empty while the queue is not full.
  std::optional<std::pair<double, double>> range() const;

  void clear();
  size_t size() const { return queue_.size(); }
  bool full() const { return queue_.size() >= options_.queue_length; }
  const std::deque<double>& queue() const { return queue_; }
  const BoxPlotFilterOptions& options() const { return options_; }

 private:
  void push(double number);

  BoxPlotFilterOptions options_;
  std::deque<double> queue_;
  size_t consecutive_rejections_ = 0;
};

}  // namespace parkloc::localize
