#pragma once
// A garage's numbering formats, learnt from numbers known to be there, and the lexicon they
// span. A garage numbers its bays in one or a few formats ("C011": a zone letter and three
// digits; "K2-086": the level, a dash, three digits), in sequence. Reading against every number
// of a format is much surer than free reading (the recognizer cannot put a letter where the
// format has a digit, and a look-alike such as "CO11" is taken as "C011"), and it assumes
// nothing about which numbers exist. The map builder reads a drive against the formats of the
// numbers a first reading agreed on (docs/MAPPING.md); the localizer lets the numbers of its
// map's formats that the map lacks compete with the map's own, so that a number outside a
// partial map is read as itself, not as the nearest number of the map (docs/LOCALIZATION.md).
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace parkloc::map {

struct NumberingOptions {
  // A format is one that at least this many known numbers follow: one misread among them must
  // not add a format of its own.
  int min_support = 2;
  // At most this many numbers per format (a format spanning more is no prior worth reading
  // against: its lexicon costs time and admits anything).
  int max_strings = 2000;
  // Bays are numbered in sequence, so the numbers not known lie near those known: a learnt
  // format spans from this far below the smallest known number to this far above the largest
  // (in the value of its open digits). It keeps out the misreads a wide format invites: "800"
  // for "008" seen upside down, "111" in a longer marking.
  int range_margin = 50;
  // A capital letter that differs among a format's numbers ("C004", "D002") is a zone letter:
  // the format opens it to every capital ("@###"), since the zones the known numbers show need
  // not be all the garage has.
  bool open_letters = false;
};

// A format: the characters of a number, '#' for a digit the format leaves open and '@' for a
// capital letter ("C###", "K2-###", "@###").
struct NumberingFormat {
  std::string pattern;
  int support = 0;  // known numbers that follow it (0: given by the user)
  // The values of the open digits it spans ("C###" from 0 to 53: C000 to C053).
  long long first = 0;
  long long last = -1;  // below first: every value
};

// The formats `numbers` follow (digits opened, zone letters too with `options.open_letters`),
// those with at least `options.min_support` numbers, each spanning its numbers' values and
// `options.range_margin` either side, and no more than `options.max_strings` numbers; most
// supported first.
std::vector<NumberingFormat> learnNumbering(const std::vector<std::string>& numbers,
                                            const NumberingOptions& options);

// True when `pattern` is a format: printable characters without spaces, at least one '#',
// spanning at most `max_strings` numbers.
bool validNumbering(const std::string& pattern, int max_strings);

// The first and the last number the format spans ("C000", "C059").
std::pair<std::string, std::string> numberingEnds(const NumberingFormat& format);

// Every string of the formats, without repeats.
std::vector<std::string> numberingLexicon(const std::vector<NumberingFormat>& formats);

// How many numbers apart two texts of one format are: the same length, the same letters and
// signs in the same places, the digits read as one number ("B2-047" and "B2-048": 1; "019"
// and "070": 51); nullopt when their formats differ or they have no digit.
std::optional<long long> numbersApart(const std::string& a, const std::string& b);

// The same, signed: how many numbers `to` comes after `from` ("B2-047" to "B2-045": -2).
std::optional<long long> numberStep(const std::string& from, const std::string& to);

}  // namespace parkloc::map
