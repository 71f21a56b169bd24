#include "mapping/numbering_format.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

namespace parkloc::mapping {
namespace {

bool isDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

int openDigits(const std::string& pattern) {
  return static_cast<int>(std::count(pattern.begin(), pattern.end(), '#'));
}

// 10^open, saturated well above any sensible cap.
long long spanOf(const std::string& pattern) {
  long long span = 1;
  for (int i = 0; i < openDigits(pattern) && span <= 1'000'000'000LL; ++i) span *= 10;
  return span;
}

}  // namespace

bool validNumbering(const std::string& pattern, int max_strings) {
  if (pattern.empty() || openDigits(pattern) == 0) return false;
  for (char c : pattern)
    if (!std::isgraph(static_cast<unsigned char>(c))) return false;
  return spanOf(pattern) <= max_strings;
}

std::vector<NumberingFormat> learnNumbering(const std::vector<std::string>& numbers,
                                            const NumberingOptions& options) {
  // Numbers by their shape: every digit opened.
  std::map<std::string, std::vector<std::string>> by_shape;
  for (const std::string& n : numbers) {
    std::string shape = n;
    for (char& c : shape)
      if (isDigit(c)) c = '#';
    if (shape.find('#') != std::string::npos) by_shape[shape].push_back(n);
  }
  std::vector<NumberingFormat> formats;
  for (auto& [shape, members] : by_shape) {
    if (static_cast<int>(members.size()) < std::max(1, options.min_support)) continue;
    // Hold the digits every member shares, from the left, while the format spans too much:
    // the level digit of "K2-086" before the hundreds of the bay number.
    std::string pattern = shape;
    for (size_t i = 0; i < pattern.size() && spanOf(pattern) > options.max_strings; ++i) {
      if (pattern[i] != '#') continue;
      const char first = members.front()[i];
      if (std::all_of(members.begin(), members.end(),
                      [&](const std::string& m) { return m[i] == first; }))
        pattern[i] = first;
    }
    if (!validNumbering(pattern, options.max_strings)) continue;
    NumberingFormat format{pattern, static_cast<int>(members.size())};
    long long smallest = spanOf(pattern), largest = -1;
    for (const std::string& m : members) {
      long long value = 0;
      for (size_t i = 0; i < pattern.size(); ++i)
        if (pattern[i] == '#') value = 10 * value + (m[i] - '0');
      smallest = std::min(smallest, value);
      largest = std::max(largest, value);
    }
    format.first = std::max(0LL, smallest - options.range_margin);
    format.last = std::min(spanOf(pattern) - 1, largest + options.range_margin);
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
    std::vector<size_t> open;
    for (size_t i = 0; i < f.pattern.size(); ++i)
      if (f.pattern[i] == '#') open.push_back(i);
    const long long span = spanOf(f.pattern);
    const long long last = f.last < f.first ? span - 1 : std::min(f.last, span - 1);
    for (long long k = std::max(0LL, f.first); k <= last; ++k) {
      std::string s = f.pattern;
      long long rest = k;
      for (auto it = open.rbegin(); it != open.rend(); ++it, rest /= 10)
        s[*it] = static_cast<char>('0' + rest % 10);
      if (seen.insert(s).second) lexicon.push_back(std::move(s));
    }
  }
  return lexicon;
}

}  // namespace parkloc::mapping
