#pragma once
// Lexicon decoding: score candidate texts (the map's texts, or those expected in a region)
// under the recognizer's CTC output and keep the best one only when it explains the crop
// about as well as the free reading does. A crop that matches nothing is reported as
// unknown with its raw reading, never forced onto the nearest entry.
#include <string>
#include <vector>

#include "ocr/ctc.h"

namespace parkloc::ocr {

struct LexiconOptions {
  // Accept the best entry when its posterior within {entries, free reading} reaches this.
  double min_posterior = 0.5;
  // ... and its mean log probability per character is above this (rejects crops that
  // are noise for every hypothesis alike).
  double min_log_prob_per_char = -2.5;
  // Prior weight of "the text is not in the lexicon" against one for the lexicon as a
  // whole: the free reading enters the posterior's denominator times this weight. Below 1
  // because the lexicon holds the texts that are really there.
  double open_world_weight = 0.05;
  // A free reading that differs from the best entry only by glyphs that look alike in some
  // fonts ("BO07" for "B007", "BU01" for "B001", see sameUpToLookAlikes) is taken as that
  // entry misread, not as evidence for an unknown text: it leaves the posterior's open-world
  // term. Unseen fonts make exactly these confusions.
  bool look_alikes_are_the_entry = true;
};

// True when `a` and `b` have the same length and every differing character pair is one of
// the look-alike groups {0 O o D Q U u}, {1 I l i |}, {5 S s}, {8 B}, {2 Z z}, {6 G b}, {9 g q}.
bool sameUpToLookAlikes(const std::string& a, const std::string& b);

struct LexiconDecoding {
  std::string raw_text;        // greedy reading
  double raw_log_prob = 0.0;   // CTC forward log probability of raw_text
  float raw_confidence = 0.f;  // PaddleOCR-style mean best-path confidence
  int best_index = -1;         // index into the candidates, -1 when none encodes
  double best_log_prob = 0.0;  // CTC forward log probability of the best candidate
  // P(best | crop) within the hypothesis set {candidates} plus the free reading (weighted
  // by open_world_weight) when it is not itself a candidate; an estimate of the
  // probability that `best` is right.
  double posterior = 0.0;
  bool matched = false;
};

// Candidates whose characters the charset cannot encode are skipped. `reading_classes`
// restricts the greedy reading (ctcGreedyDecode); empty: every class.
LexiconDecoding decodeWithLexicon(const CtcMatrix& probs, const Charset& charset,
                                  const std::vector<std::string>& candidates,
                                  const LexiconOptions& options = {},
                                  const std::vector<int>& reading_classes = {});

}  // namespace parkloc::ocr
