#include "ocr/ctc.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>

#include "common/error.h"

namespace parkloc::ocr {
namespace {

constexpr double kNegInf = -std::numeric_limits<double>::infinity();

double logAdd(double a, double b) {
  if (a == kNegInf) return b;
  if (b == kNegInf) return a;
  const double m = std::max(a, b);
  return m + std::log1p(std::exp(-std::abs(a - b)));
}

int utf8Length(unsigned char lead) {
  if (lead < 0x80) return 1;
  if ((lead >> 5) == 0x6) return 2;
  if ((lead >> 4) == 0xE) return 3;
  if ((lead >> 3) == 0x1E) return 4;
  return 1;
}

}  // namespace

std::vector<std::string> splitUtf8(const std::string& text) {
  std::vector<std::string> out;
  for (size_t i = 0; i < text.size();) {
    size_t n = static_cast<size_t>(utf8Length(static_cast<unsigned char>(text[i])));
    if (i + n > text.size()) n = 1;
    out.push_back(text.substr(i, n));
    i += n;
  }
  return out;
}

Charset::Charset(std::vector<std::string> characters) : characters_(std::move(characters)) {
  for (size_t i = 0; i < characters_.size(); ++i)
    sorted_.emplace_back(characters_[i], static_cast<int>(i) + 1);
  // Stable, so a character listed twice encodes to its first class.
  std::stable_sort(sorted_.begin(), sorted_.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
}

Charset Charset::fromDictionaryFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw IoError("cannot open character dictionary " + path);
  std::vector<std::string> characters;
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    characters.push_back(line);
  }
  if (characters.empty()) throw InputError("empty character dictionary " + path);
  characters.push_back(" ");
  return Charset(std::move(characters));
}

std::optional<std::vector<int>> Charset::encode(const std::string& text) const {
  std::vector<int> classes;
  for (const auto& ch : splitUtf8(text)) {
    auto it = std::lower_bound(
        sorted_.begin(), sorted_.end(), ch,
        [](const auto& entry, const std::string& key) { return entry.first < key; });
    if (it == sorted_.end() || it->first != ch) return std::nullopt;
    classes.push_back(it->second);
  }
  return classes;
}

std::string Charset::decode(const std::vector<int>& classes) const {
  std::string text;
  for (int c : classes)
    if (c >= 1 && c < classCount()) text += character(c);
  return text;
}

std::vector<int> Charset::readingClasses(const std::string& alphabet) const {
  std::vector<int> classes;
  if (alphabet.empty()) return classes;
  classes.push_back(0);
  for (const auto& ch : splitUtf8(alphabet)) {
    const auto encoded = encode(ch);
    if (!encoded) throw InputError("reading alphabet: character '" + ch + "' is not in the recognizer's dictionary");
    classes.push_back(encoded->front());
  }
  std::sort(classes.begin(), classes.end());
  classes.erase(std::unique(classes.begin(), classes.end()), classes.end());
  return classes;
}

GreedyResult ctcGreedyDecode(const CtcMatrix& probs, const std::vector<int>& classes) {
  GreedyResult result;
  int previous = -1;
  double confidence_sum = 0.0;
  for (int t = 0; t < probs.steps; ++t) {
    const float* row = probs.data + static_cast<size_t>(t) * probs.classes;
    int best = 0;
    if (classes.empty()) {
      best = static_cast<int>(std::max_element(row, row + probs.classes) - row);
    } else {
      for (int c : classes)
        if (c < probs.classes && row[c] > row[best]) best = c;
    }
    if (best != 0 && best != previous) {
      result.classes.push_back(best);
      confidence_sum += row[best];
    }
    previous = best;
  }
  if (!result.classes.empty())
    result.mean_confidence = static_cast<float>(confidence_sum / result.classes.size());
  return result;
}

double ctcLogProbability(const CtcMatrix& probs, const std::vector<int>& labels) {
  // Extended sequence: blank, l1, blank, l2, ..., lL, blank (length 2L+1).
  const int S = 2 * static_cast<int>(labels.size()) + 1;
  if (probs.steps == 0) return labels.empty() ? 0.0 : kNegInf;
  auto symbol = [&](int s) { return (s % 2 == 0) ? 0 : labels[s / 2]; };
  auto logp = [&](int t, int s) {
    const float p = probs.at(t, symbol(s));
    return p > 0.f ? std::log(static_cast<double>(p)) : kNegInf;
  };
  std::vector<double> alpha(S, kNegInf), next(S, kNegInf);
  alpha[0] = logp(0, 0);
  if (S > 1) alpha[1] = logp(0, 1);
  for (int t = 1; t < probs.steps; ++t) {
    for (int s = 0; s < S; ++s) {
      double a = alpha[s];
      if (s >= 1) a = logAdd(a, alpha[s - 1]);
      // Skipping the blank between two labels is allowed only when they differ.
      if (s >= 2 && s % 2 == 1 && symbol(s) != symbol(s - 2)) a = logAdd(a, alpha[s - 2]);
      next[s] = a == kNegInf ? kNegInf : a + logp(t, s);
    }
    std::swap(alpha, next);
  }
  return S > 1 ? logAdd(alpha[S - 1], alpha[S - 2]) : alpha[0];
}

}  // namespace parkloc::ocr
