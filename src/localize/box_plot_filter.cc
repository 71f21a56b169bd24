#include "localize/box_plot_filter.h"

#include <algorithm>
#include <cctype>

namespace parkloc::localize {
namespace {

double quantileSorted(const std::vector<double>& sorted, double p) {
  const double position = p * static_cast<double>(sorted.size() - 1);
  const size_t below = static_cast<size_t>(position);
  const size_t above = std::min(below + 1, sorted.size() - 1);
  const double fraction = position - static_cast<double>(below);
  return sorted[below] + fraction * (sorted[above] - sorted[below]);
}

}  // namespace

std::optional<Quartiles> computeQuartiles(std::vector<double> values) {
  if (values.empty()) return std::nullopt;
  std::sort(values.begin(), values.end());
  return Quartiles{quantileSorted(values, 0.25), quantileSorted(values, 0.5),
                   quantileSorted(values, 0.75)};
}

std::optional<int> parkingNumberValue(const std::string& text) {
  size_t end = text.size();
  while (end > 0 && !std::isdigit(static_cast<unsigned char>(text[end - 1]))) --end;
  if (end == 0) return std::nullopt;
  size_t begin = end;
  while (begin > 0 && std::isdigit(static_cast<unsigned char>(text[begin - 1]))) --begin;
  // Leading zeros do not count towards the length limit ("0098" is 98).
  size_t first = begin;
  while (first + 1 < end && text[first] == '0') ++first;
  if (end - first > 9) return std::nullopt;
  return std::stoi(text.substr(first, end - first));
}

std::optional<std::pair<double, double>> BoxPlotFilter::range() const {
  if (!full() || queue_.empty()) return std::nullopt;
  const auto q = computeQuartiles({queue_.begin(), queue_.end()});
  const double half_width = options_.iqr_factor * q->iqr();
  return std::make_pair(q->median - half_width, q->median + half_width);
}

bool BoxPlotFilter::accept(double number) {
  const auto bounds = range();
  if (!bounds || (number >= bounds->first && number <= bounds->second)) {
    push(number);
    consecutive_rejections_ = 0;
    return true;
  }
  ++consecutive_rejections_;
  if (options_.reset_after_rejections > 0 &&
      consecutive_rejections_ >= options_.reset_after_rejections) {
    clear();
  }
  return false;
}

void BoxPlotFilter::clear() {
  queue_.clear();
  consecutive_rejections_ = 0;
}

void BoxPlotFilter::remember(double number) {
  push(number);
  consecutive_rejections_ = 0;
}

void BoxPlotFilter::push(double number) {
  queue_.push_back(number);
  while (queue_.size() > std::max<size_t>(options_.queue_length, 1)) queue_.pop_front();
}

}  // namespace parkloc::localize
