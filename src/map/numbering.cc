#include "map/numbering.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

namespace parkloc::map {
namespace {

constexpr char kDigit = '#';
constexpr char kLetter = '@';

bool isDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool isCapital(char c) { return c >= 'A' && c <= 'Z'; }

// How many numbers the pattern spans, the digits' range aside; saturated well above any cap.
long long spanOf(const std::string& pattern) {
  long long span = 1;
  for (char c : pattern) {
    if (span > 1'000'000'000LL) break;
    if (c == kDigit) span *= 10;
    if (c == kLetter) span *= 26;
  }
  return span;
}

// 10^(open digits): the values the digits of the pattern can take.
long long digitValues(const std::string& pattern) {
  long long values = 1;
  for (char c : pattern)
    if (c == kDigit && values <= 1'000'000'000LL) values *= 10;
  return values;
}

// The combinations of the pattern's open letters (26 per letter).
long long letterCombinations(const std::string& pattern) {
  return spanOf(pattern) / digitValues(pattern);
}

// The last value of the format's digits (NumberingFormat::last, every value when below first).
long long lastValue(const NumberingFormat& f) {
  const long long values = digitValues(f.pattern);
  return f.last < f.first ? values - 1 : std::min(f.last, values - 1);
}

// How many numbers the format spans: its letters' and its digits' range.
long long spannedBy(const NumberingFormat& f) {
  return letterCombinations(f.pattern) * (lastValue(f) - f.first + 1);
}

// The format's number whose open digits read `value` and whose open letters are the
// `letters`-th combination (A..Z per letter, the last letter fastest).
std::string numberOf(const NumberingFormat& f, long long letters, long long value) {
  std::string s = f.pattern;
  for (auto it = s.rbegin(); it != s.rend(); ++it) {
    if (*it == kDigit) {
      *it = static_cast<char>('0' + value % 10);
      value /= 10;
    } else if (*it == kLetter) {
      *it = static_cast<char>('A' + letters % 26);
      letters /= 26;
    }
  }
  return s;
}

}  // namespace

bool validNumbering(const std::string& pattern, int max_strings) {
  if (pattern.empty() || pattern.find(kDigit) == std::string::npos) return false;
  for (char c : pattern)
    if (!std::isgraph(static_cast<unsigned char>(c))) return false;
  return spanOf(pattern) <= max_strings;
}

std::vector<NumberingFormat> learnNumbering(const std::vector<std::string>& numbers,
                                            const NumberingOptions& options) {
  // Numbers by their shape: every digit opened, and with open_letters every capital letter.
  std::map<std::string, std::vector<std::string>> by_shape;
  for (const std::string& n : numbers) {
    std::string shape = n;
    for (char& c : shape) {
      if (isDigit(c)) c = kDigit;
      if (options.open_letters && isCapital(c)) c = kLetter;
    }
    if (shape.find(kDigit) != std::string::npos) by_shape[shape].push_back(n);
  }
  std::vector<NumberingFormat> formats;
  for (const auto& entry : by_shape) {
    const std::vector<std::string>& members = entry.second;  // a lambda may not capture a binding
    const std::string& shape = entry.first;
    if (static_cast<int>(members.size()) < std::max(1, options.min_support)) continue;
    const auto shared = [&](size_t i) {
      return std::all_of(members.begin(), members.end(),
                         [&](const std::string& m) { return m[i] == members.front()[i]; });
    };
    // A letter every member shares is part of the format ("K" of "K2-086"); one that differs
    // among them is a zone letter, open to every capital.
    std::string pattern = shape;
    for (size_t i = 0; i < pattern.size(); ++i)
      if (pattern[i] == kLetter && shared(i)) pattern[i] = members.front()[i];
    // The bay number is the last run of digits; a digit before it that every member shares
    // (the level of "K2-086") is part of the format, not of the number's value.
    size_t bay = pattern.find_last_of(kDigit);
    while (bay > 0 && pattern[bay - 1] == kDigit) --bay;
    for (size_t i = 0; i < bay; ++i)
      if (pattern[i] == kDigit && shared(i)) pattern[i] = members.front()[i];
    // The format spans its members' values and the margin either side.
    NumberingFormat format{pattern, static_cast<int>(members.size())};
    long long smallest = digitValues(pattern), largest = -1;
    for (const std::string& m : members) {
      long long value = 0;
      for (size_t i = 0; i < pattern.size(); ++i)
        if (pattern[i] == kDigit) value = 10 * value + (m[i] - '0');
      smallest = std::min(smallest, value);
      largest = std::max(largest, value);
    }
    format.first = std::max(0LL, smallest - options.range_margin);
    format.last = std::min(digitValues(pattern) - 1, largest + options.range_margin);
    if (spannedBy(format) > options.max_strings) {
      // Zone letters open make too many numbers: each letter its own format, as the numbers
      // show them.
      if (options.open_letters && pattern.find(kLetter) != std::string::npos) {
        NumberingOptions closed = options;
        closed.open_letters = false;
        for (const NumberingFormat& f : learnNumbering(members, closed)) formats.push_back(f);
      }
      continue;
    }
    formats.push_back(format);
  }
  std::stable_sort(formats.begin(), formats.end(),
                   [](const auto& a, const auto& b) { return a.support > b.support; });
  return formats;
}

std::vector<std::string> numberingLexicon(const std::vector<NumberingFormat>& formats) {
  std::vector<std::string> lexicon;
  std::set<std::string> seen;
  for (const NumberingFormat& f : formats) {
    const long long letters = letterCombinations(f.pattern), last = lastValue(f);
    for (long long l = 0; l < letters; ++l)
      for (long long v = std::max(0LL, f.first); v <= last; ++v)
        if (std::string s = numberOf(f, l, v); seen.insert(s).second)
          lexicon.push_back(std::move(s));
  }
  return lexicon;
}

std::pair<std::string, std::string> numberingEnds(const NumberingFormat& f) {
  return {numberOf(f, 0, std::max(0LL, f.first)),
          numberOf(f, letterCombinations(f.pattern) - 1, lastValue(f))};
}

std::optional<long long> numberStep(const std::string& from, const std::string& to) {
  if (from.size() != to.size() || from.size() > 18) return std::nullopt;
  long long a = 0, b = 0;
  bool digits = false;
  for (size_t k = 0; k < from.size(); ++k) {
    const bool ca = std::isdigit(static_cast<unsigned char>(from[k])) != 0;
    const bool cb = std::isdigit(static_cast<unsigned char>(to[k])) != 0;
    if (ca != cb || (!ca && from[k] != to[k])) return std::nullopt;
    if (ca) {
      a = 10 * a + (from[k] - '0');
      b = 10 * b + (to[k] - '0');
      digits = true;
    }
  }
  if (!digits) return std::nullopt;
  return b - a;
}

std::optional<long long> numbersApart(const std::string& a, const std::string& b) {
  const auto step = numberStep(a, b);
  if (!step) return std::nullopt;
  return *step < 0 ? -*step : *step;
}

}  // namespace parkloc::map
