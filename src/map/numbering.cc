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

// How many numbers the format spans: its letters' and its digits' range.
long long spannedBy(const NumberingFormat& f) {
  const long long values = digitValues(f.pattern);
  const long long digits = f.last < f.first ? values : std::min(f.last, values - 1) - f.first + 1;
  return spanOf(f.pattern) / values * digits;
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
  for (auto& [shape, members] : by_shape) {
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
    const auto ranged = [&](const std::string& p) {
      NumberingFormat format{p, static_cast<int>(members.size())};
      long long smallest = digitValues(p), largest = -1;
      for (const std::string& m : members) {
        long long value = 0;
        for (size_t i = 0; i < p.size(); ++i)
          if (p[i] == kDigit) value = 10 * value + (m[i] - '0');
        smallest = std::min(smallest, value);
        largest = std::max(largest, value);
      }
      format.first = std::max(0LL, smallest - options.range_margin);
      format.last = std::min(digitValues(p) - 1, largest + options.range_margin);
      return format;
    };
    const NumberingFormat format = ranged(pattern);
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
    std::vector<size_t> digits, letters;
    for (size_t i = 0; i < f.pattern.size(); ++i) {
      if (f.pattern[i] == kDigit) digits.push_back(i);
      if (f.pattern[i] == kLetter) letters.push_back(i);
    }
    const long long values = digitValues(f.pattern);
    const long long last = f.last < f.first ? values - 1 : std::min(f.last, values - 1);
    long long letter_combinations = 1;
    for (size_t k = 0; k < letters.size(); ++k) letter_combinations *= 26;
    for (long long l = 0; l < letter_combinations; ++l)
      for (long long v = std::max(0LL, f.first); v <= last; ++v) {
        std::string s = f.pattern;
        long long rest = v;
        for (auto it = digits.rbegin(); it != digits.rend(); ++it, rest /= 10)
          s[*it] = static_cast<char>('0' + rest % 10);
        rest = l;
        for (auto it = letters.rbegin(); it != letters.rend(); ++it, rest /= 26)
          s[*it] = static_cast<char>('A' + rest % 26);
        if (seen.insert(s).second) lexicon.push_back(std::move(s));
      }
  }
  return lexicon;
}

}  // namespace parkloc::map
