#include "localize/level_estimate.h"

#include <fmt/format.h>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <regex>

#include "common/error.h"
#include "localize/shared_places.h"

namespace parkloc::localize {

std::string levelNameKey(const std::string& text) {
  std::string out;
  for (const char c : text)
    if (!std::isspace(static_cast<unsigned char>(c)))
      out.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  return out;
}

std::optional<std::string> levelNamedBy(const std::vector<std::string>& levels,
                                        const std::string& text) {
  const std::string key = levelNameKey(text);
  for (const std::string& level : levels)
    if (levelNameKey(level) == key) return level;
  return std::nullopt;
}

bool looksLikeLevelSign(const std::string& text) {
  // A letter or two and a level number ("B2", "P1", "UG1"), or a minus and one ("-1").
  static const std::regex pattern("^([A-Z]{1,3}[0-9]{1,2}|-[0-9]{1,2})$");
  return std::regex_match(levelNameKey(text), pattern);
}

LevelEstimate::LevelEstimate(const map::HdMap& map, const LevelOptions& options, std::string hint)
    : map_(map), options_(options), hint_(std::move(hint)) {
  levels_ = map::distinctLevels(map);
  if (levels_.empty()) levels_.push_back("");
  if (!hint_.empty() && std::find(levels_.begin(), levels_.end(), hint_) == levels_.end()) {
    std::string known;
    for (const auto& l : levels_) known += (known.empty() ? "" : ", ") + l;
    throw InputError(
        fmt::format("level \"{}\" is not a level of the map (it has: {})", hint_, known));
  }
  reset();
}

void LevelEstimate::reset() {
  const size_t n = levels_.size();
  p_.assign(n, 1.0 / static_cast<double>(n));
  if (!hint_.empty() && n > 1)
    for (size_t i = 0; i < n; ++i)
      p_[i] = levels_[i] == hint_ ? options_.hint_probability
                                  : (1.0 - options_.hint_probability) / static_cast<double>(n - 1);
  started_ = false;
  last_timestamp_ = last_text_time_ = 0.0;
  unknown_signs_.clear();
  decide();
}

void LevelEstimate::predict(double timestamp) {
  if (!started_) last_text_time_ = timestamp;
  const bool first = !started_;
  const double previous = last_timestamp_;
  started_ = true;
  last_timestamp_ = timestamp;
  const size_t n = levels_.size();
  // The part of the interval that lies on a text-free stretch long enough to be a ramp.
  const double dt = timestamp - std::max(previous, last_text_time_ + options_.ramp_after_s);
  if (first || n < 2 || !(dt > 0.0)) return;
  const double q = 1.0 - std::exp(-options_.change_rate_per_s * dt);
  for (double& p : p_) p = (1.0 - q) * p + q * (1.0 - p) / static_cast<double>(n - 1);
  decide();
}

void LevelEstimate::update(const std::vector<CameraResult>& cameras,
                           const std::vector<Association>& associations,
                           std::vector<std::string>& warnings) {
  const size_t n = levels_.size();
  for (const Association& a : associations)
    if (a.verdict == AssociationVerdict::kAccepted) last_text_time_ = last_timestamp_;
  if (n < 2) return;
  // The strongest evidence of each distinct text this frame set: the levels it fits.
  struct Evidence {
    std::set<std::string> levels;
    double ratio = 0.0;
  };
  std::map<std::string, Evidence> by_text;
  size_t k = 0;
  for (const CameraResult& camera : cameras)
    for (const ocr::TextInstance& instance : camera.instances) {
      const Association* a = k < associations.size() ? &associations[k] : nullptr;
      ++k;
      if (!instance.read || instance.partial || instance.second_opinion || instance.text.empty() ||
          instance.recognition_score < options_.min_recognition_score)
        continue;
      Evidence e;
      if (const auto named = levelNamedBy(levels_, instance.text)) {
        e.levels = {*named};
        e.ratio = options_.sign_ratio;
      } else if (a && a->verdict == AssociationVerdict::kAccepted && !a->landmark_id.empty()) {
        if (const map::Landmark* l = map_.findById(a->landmark_id))
          e.levels = levelsWithTextAt(map_, instance.text, *l, options_.shared_place_m);
        e.ratio = options_.place_ratio;
      } else {
        e.levels = map::levelsWithText(map_, instance.text);
        e.ratio = options_.text_ratio;
        if (e.levels.empty() && instance.cls != map::TextClass::kParkingNumber &&
            looksLikeLevelSign(instance.text) &&
            unknown_signs_.insert(levelNameKey(instance.text)).second)
          warnings.push_back(
              fmt::format("level sign \"{}\" names no level of the map: ignored", instance.text));
      }
      if (e.levels.empty() || e.levels.size() >= n) continue;
      Evidence& kept = by_text[instance.text];
      if (e.ratio > kept.ratio) kept = std::move(e);
    }
  if (by_text.empty()) return;

  std::vector<double> log_likelihood(n, 0.0);
  for (const auto& [text, e] : by_text)
    for (size_t i = 0; i < n; ++i)
      if (e.levels.count(levels_[i])) log_likelihood[i] += std::log(e.ratio);
  const double top = *std::max_element(log_likelihood.begin(), log_likelihood.end());
  const double lowest = top - std::log(std::max(options_.max_frame_ratio, 1.0));
  double sum = 0.0;
  for (size_t i = 0; i < n; ++i) {
    p_[i] *= std::exp(std::max(log_likelihood[i], lowest) - top);
    sum += p_[i];
  }
  for (double& p : p_) p = std::max(p / sum, options_.min_probability);
  sum = 0.0;
  for (const double p : p_) sum += p;
  for (double& p : p_) p /= sum;
  decide();
}

void LevelEstimate::decide() {
  const auto best = std::max_element(p_.begin(), p_.end());
  belief_.level = levels_[static_cast<size_t>(best - p_.begin())];
  belief_.probability = *best;
  belief_.decided = *best >= options_.decided_probability;
}

}  // namespace parkloc::localize
