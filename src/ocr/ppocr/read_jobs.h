#pragma once
// Read jobs: what the reading cascade reads, and against what. A detected box becomes a job
// with its lexicon and prior: the whole (floor) lexicon, or under a predicted pose the texts
// the map places near the box, with the parts of them a cut would leave where the box may run
// out of sight, read only the way round those texts read.
#include <deque>
#include <string>
#include <vector>

#include "ocr/cut_parts.h"
#include "ocr/lexicon.h"
#include "ocr/ppocr/detection.h"
#include "ocr/ppocr/floor_views.h"
#include "ocr/ppocr/map_prior_options.h"
#include "ocr/quad.h"
#include "ocr/text_spotter.h"

namespace parkloc::ocr {

// One quad to read: where it is, which texts it may be, whether to try it upside down.
struct ReadJob {
  Quad quad;
  float detection_score = 0.f;
  const std::vector<std::string>* lexicon = nullptr;
  // The lexicon prior to decode under; null: ReadingOptions::lexicon.
  const LexiconOptions* prior = nullptr;
  // When `lexicon` is cut->texts: which whole text each entry stands for.
  const CutCandidates* cut = nullptr;
  // `lexicon` holds the texts placed near the box (SpotRequest::narrow_to_placed_texts).
  bool placed = false;
  // ... and when the box lies on one of them, those texts whole (`lexicon` may hold parts of
  // them too); null otherwise.
  const std::vector<std::string>* placed_near = nullptr;
  bool onPlacedText() const { return placed_near != nullptr; }
  // The texts whose characters a free reading may use: `lexicon`, or the whole floor
  // lexicon when `lexicon` is the part of it placed near the box. Null: `lexicon`.
  const std::vector<std::string>* reading_lexicon = nullptr;
  bool try_both_directions = true;
  // The detector is sure of this box: it is reported even when its reading is not
  // (text empty, raw_text the greedy reading).
  bool keep_unread = false;
  // The crop is read from the quad grown by these factors (along, across the text).
  float read_expand_x = 1.f, read_expand_y = 1.f;
  // Read by the fallback recognizer alone, once, when there is one: a box that only a
  // lexicon match may keep (a window beyond the floor view) needs no free reading.
  bool fallback_only = false;
};

// Jobs with the lexicons made for them, which they point into.
struct ReadJobSet {
  std::vector<ReadJob> jobs;
  std::deque<std::vector<std::string>> placed_lexicons;
  std::deque<CutCandidates> cut_lexicons;

  ReadJobSet() = default;
  ReadJobSet(const ReadJobSet&) = delete;
  ReadJobSet& operator=(const ReadJobSet&) = delete;
};

// Adds a job for each box `found` by the detector of `role`. `floor`: where a floor-view
// detection's image lies (null for the other roles); with SpotRequest::placed_floor_texts,
// its boxes are read under the map's prior, and a window's boxes with no text placed near them
// are not read at all. A floor box at least `confident_box_score` is kept unread.
void addDetectedJobs(ReadJobSet& set, const Detections& found, DetectorRole role,
                     const SpotRequest& request, const FloorWindow* floor,
                     const MapPriorOptions& options, float confident_box_score);

}  // namespace parkloc::ocr
