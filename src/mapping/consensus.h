#pragma once
// Stage 2 of map building, the consensus reading: which sightings are one text, and what it
// says. Sightings are grouped by place (their cast centres in the dead-reckoned frame), and in
// each place the reading seen in the most frame sets wins: a misread in one frame set (a 6 for
// an 8, a digit lost at the image border) is outvoted and dropped, never a landmark of its own.
// A place makes a landmark only when its reading was seen in enough frame sets and agrees
// with most of what was read there. Two places with one reading: near each other they are the
// same text seen again after a loop (merged; this closes the loop in the estimation), far
// apart they are a number painted twice or a misread that won another number's place: the one
// where it was read in min_margin times the frame sets of every other keeps it, else none.
#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "map/landmark.h"
#include "mapping/row_sequence.h"
#include "mapping/sighting_cast.h"
#include "mapping/sightings.h"

namespace parkloc::mapping {

struct ConsensusOptions {
  // Sightings whose cast centres lie within this of a place's centre are at that place: well
  // under the spacing of parking numbers (2.3 m or more), well over the cast's error at range.
  double place_radius_m = 1.0;
  // Sightings cast from further than this are left out: the floor's footprint of a pixel
  // grows with range, and with it the cast's error.
  double max_range_m = 9.0;
  // A landmark's reading was seen in at least this many frame sets (the targets' legibility
  // bar) ...
  int min_frame_sets = 3;
  // ... and in at least this share of the frame sets that read anything at its place ...
  double min_agreement = 0.5;
  // ... and in this many times the frame sets of the runner-up reading: a place where two
  // readings compete (a 2 read as 7 in a font that blurs them) is left out rather than
  // guessed.
  double min_margin = 2.0;
  // ... and it was confirmed in at least this many of its frame sets: read by the first
  // recognizer and, when the drive was read against a numbering, as one of its numbers.
  // Readings the fallback recognizer alone matched to the numbering (second opinions) and
  // free readings off the numbering vote in the place's count, where they outvote the first
  // reader's misreads of a number, but make no landmark by themselves. The numbering a build
  // learns spans numbers that are not painted, and the fallback matches other floor texts to
  // them (an upside-down EXIT, raw "11X3", read as 113 in 47 frame sets of a validation drive
  // and never by the first reader); a free reading that recurs is a car's plate or part of a
  // number ("04", "LI110" for B1-115 on the train drives). 0: every reading confirms.
  int min_confirmed_frame_sets = 3;
  // Two places with the same winning reading this close are one text seen twice (a loop) ...
  double loop_radius_m = 4.0;
  // ... unless both were read in this many of the same frame sets: a text is at one place in
  // a frame set, so they are two texts, one of them misread as the other (a 1 read as 2 in a
  // font that blurs them, next to the 2 in the bay beside it). 0: off.
  int min_frame_sets_seen_apart = 2;
  // Bays are numbered in sequence along a row (a bay is 2.3-3 m wide): two landmarks of one
  // format within this distance whose numbers are not consecutive hold a misread that won its
  // place, and the one seen in fewer frame sets is left out (070 in 18 frame sets beside 019
  // in 66, for 020; 101 in 3 beside 103 in 22, for 102, on the train drives, where no two true
  // landmarks within 4 m broke the sequence). 0: off.
  double sequence_radius_m = 4.0;
  // The same sequence decides a place left out for a close runner-up or too little agreement:
  // its most seen reading becomes a landmark when it is consecutive to a landmark within
  // sequence_radius_m, no rival reading there is, and it is not a landmark elsewhere (a
  // number is painted once on a level). Confirmed as any landmark must be. False: off.
  bool sequence_decides_contests = true;
  // ... and the reading it takes need not be the most seen one: of the place's readings the
  // one consecutive to a landmark nearby, when only one is (a worn 7 read as 2 more often than
  // as 7, beside a landmark 6). Seen in min_frame_sets and confirmed as any landmark must be.
  // False: only the most seen reading.
  bool sequence_decides_for_any_reading = true;
  // Further along a row than sequence_radius_m the row's numbering judges a place
  // (row_sequence.h): a contested place takes the one reading seen in min_frame_sets that
  // the rows or a landmark within sequence_radius_m put in sequence, and of two landmarks out
  // of sequence side by side the one the rows allow stays whichever was seen more. False: off.
  bool row_sequence = true;
  RowSequenceOptions row;
};

// One text of the map to be: the sightings that agree on its reading.
struct TextTrack {
  std::string text;
  map::TextClass cls = map::TextClass::kParkingNumber;
  std::vector<size_t> sightings;  // indices into the sightings, those that read `text`
  int frame_sets = 0;             // distinct (drive, frame set) among them
  int misreads = 0;               // sightings at its place that read something else
  Eigen::Vector2d place = Eigen::Vector2d::Zero();
};

// A place whose best reading was seen in enough frame sets but made no landmark, and why.
struct UndecidedPlace {
  Eigen::Vector2d place = Eigen::Vector2d::Zero();  // in the dead-reckoned frame
  std::string why;  // "disagreement", "close runner-up" or "unconfirmed"
  std::vector<std::pair<std::string, int>> readings;  // (text, frame sets), most first
};

struct Consensus {
  std::vector<TextTrack> tracks;
  size_t unplaced = 0;     // sightings whose rays missed the floor or beyond max_range_m
  size_t misreads = 0;     // sightings outvoted at their place
  size_t weak_places = 0;  // places whose reading was seen too rarely or disagreed too much
  // Places whose reading was too rarely confirmed (min_confirmed_frame_sets).
  size_t unconfirmed_places = 0;
  size_t loops = 0;        // places merged with another of the same reading
  // Readings that won two places far apart, none seen in min_margin times the frame sets of
  // the other: left out of the map.
  std::vector<std::string> duplicates;
  // ... one of them so seen: kept there, the others taken for misreads of other numbers.
  std::vector<std::string> outweighed_duplicates;
  std::vector<UndecidedPlace> undecided;
  // Landmarks left out for breaking the numbering's sequence beside a better-seen one.
  std::vector<std::string> out_of_sequence;
  // Contested places the sequence decided (ConsensusOptions::sequence_decides_contests).
  std::vector<std::string> decided_by_sequence;
};

// `cast[i]` is sightings[i] cast through its drive's poses (empty: unplaced); all drives in one
// frame.
Consensus formConsensus(const std::vector<Sighting>& sightings,
                        const std::vector<std::optional<CastSighting>>& cast,
                        const ConsensusOptions& options);

}  // namespace parkloc::mapping
