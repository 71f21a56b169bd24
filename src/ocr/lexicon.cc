#include "ocr/lexicon.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace parkloc::ocr {
namespace {

// The look-alike group of a character; the character itself when it is in none.
std::string lookAlikeGroup(const std::string& ch) {
  static const std::vector<std::pair<std::string, std::string>> kGroups = {
      {"0OoDQUu", "0"}, {"1Ili|", "1"}, {"5Ss", "5"}, {"8B", "8"},
      {"2Zz", "2"},     {"6Gb", "6"},   {"9gq", "9"}};
  if (ch.size() == 1)
    for (const auto& [members, group] : kGroups)
      if (members.find(ch[0]) != std::string::npos) return group;
  return ch;
}

}  // namespace

bool sameUpToLookAlikes(const std::string& a, const std::string& b) {
  const auto ca = splitUtf8(a), cb = splitUtf8(b);
  if (ca.size() != cb.size()) return false;
  for (size_t i = 0; i < ca.size(); ++i)
    if (ca[i] != cb[i] && lookAlikeGroup(ca[i]) != lookAlikeGroup(cb[i])) return false;
  return true;
}

LexiconDecoding decodeWithLexicon(const CtcMatrix& probs, const Charset& charset,
                                  const std::vector<std::string>& candidates,
                                  const LexiconOptions& options,
                                  const std::vector<int>& reading_classes) {
  constexpr double kNegInf = -std::numeric_limits<double>::infinity();
  LexiconDecoding out;
  const GreedyResult greedy = ctcGreedyDecode(probs, reading_classes);
  out.raw_text = charset.decode(greedy.classes);
  out.raw_confidence = greedy.mean_confidence;
  out.raw_log_prob = ctcLogProbability(probs, greedy.classes);

  std::vector<double> log_probs(candidates.size(), kNegInf);
  bool raw_is_candidate = false;
  double best = kNegInf;
  for (size_t i = 0; i < candidates.size(); ++i) {
    const auto labels = charset.encode(candidates[i]);
    if (!labels || labels->empty()) continue;
    log_probs[i] = ctcLogProbability(probs, *labels);
    if (candidates[i] == out.raw_text) raw_is_candidate = true;
    if (log_probs[i] > best) {
      best = log_probs[i];
      out.best_index = static_cast<int>(i);
    }
  }
  if (out.best_index < 0 || best == kNegInf) return out;
  out.best_log_prob = best;

  // Posterior by log-sum-exp over the hypothesis set; the same text listed twice counts once.
  double sum = 0.0;
  std::vector<std::string> seen;
  for (size_t i = 0; i < candidates.size(); ++i) {
    if (log_probs[i] == kNegInf) continue;
    if (std::find(seen.begin(), seen.end(), candidates[i]) != seen.end()) continue;
    seen.push_back(candidates[i]);
    sum += std::exp(log_probs[i] - best);
  }
  if (options.look_alikes_are_the_entry &&
      sameUpToLookAlikes(out.raw_text, candidates[out.best_index]))
    raw_is_candidate = true;
  if (!raw_is_candidate && out.raw_log_prob > kNegInf)
    sum += options.open_world_weight * std::exp(out.raw_log_prob - best);
  out.posterior = 1.0 / sum;

  const auto length = splitUtf8(candidates[out.best_index]).size();
  const double per_char = best / static_cast<double>(std::max<size_t>(length, 1));
  out.matched = out.posterior >= options.min_posterior && per_char >= options.min_log_prob_per_char;
  return out;
}

}  // namespace parkloc::ocr
