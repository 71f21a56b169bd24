#pragma once
// The garage's numbering format, learnt from the numbers a first reading agreed on, and the
// lexicon it spans. A garage numbers its bays in one or a few formats ("C011": a zone letter
// and three digits; "K2-086": the level, a dash, three digits). Reading against every string of
// such a format is much surer than free reading (the recognizer cannot put a letter where the
// format has a digit, and a look-alike such as "CO11" is taken as "C011"), yet it assumes
// nothing about which numbers exist: the lexicon spans the format, not a map.
#include <string>
#include <vector>

namespace parkloc::mapping {

struct NumberingOptions {
  // Learn the formats from a first, free reading of every `survey_step`-th frame set, then
  // read the drive again against the lexicon they span. False: free reading only (and the
  // formats the user gives, if any).
  bool learn = true;
  int survey_step = 3;
  // A format is one that at least this many agreed numbers follow: one misread that won a
  // place must not add a format of its own.
  int min_support = 2;
  // At most this many strings per format: digit positions that every supporting number shares
  // are held, from the left, until the format spans no more (e.g. "K2-###", not "K#-###").
  int max_strings = 2000;
  // Bays are numbered in sequence, so the numbers the first reading missed lie near those it
  // agreed on: a learnt format spans from this far below the smallest agreed number to this
  // far above the largest (in the value of its open digits). It keeps out the misreads a wide
  // format invites: "800" for "008" seen upside down, "111" in a longer marking.
  int range_margin = 50;
};

// A format: the characters of a number, '#' for a digit the format leaves open
// ("C###", "K2-###").
struct NumberingFormat {
  std::string pattern;
  int support = 0;  // agreed numbers that follow it (0: given by the user)
  // The values of the open digits it spans ("C###" from 0 to 53: C000 to C053).
  long long first = 0;
  long long last = -1;  // below first: every value
};

// The formats `numbers` follow (digits opened, then held where the format would span more than
// `options.max_strings`), those with at least `options.min_support` numbers, most supported
// first, each spanning its numbers' values and `options.range_margin` either side.
std::vector<NumberingFormat> learnNumbering(const std::vector<std::string>& numbers,
                                            const NumberingOptions& options);

// True when `pattern` is a format: printable characters without spaces, at least one '#',
// spanning at most `max_strings` strings.
bool validNumbering(const std::string& pattern, int max_strings);

// Every string of the formats, without repeats.
std::vector<std::string> numberingLexicon(const std::vector<NumberingFormat>& formats);

}  // namespace parkloc::mapping
