#pragma once
// What the map says about a floor box under a predicted pose (SpotRequest::placed_floor_texts):
// which texts it may be and how strongly, which way round it reads, which class it may take,
// what a cut may leave of it and how large it is painted. Read jobs (read_jobs.h) and the rules
// applied after reading (map_prior_rules.h) share these options.
#include <cmath>
#include <optional>

#include "ocr/lexicon.h"
#include "ocr/placed_size.h"

namespace parkloc::ocr {

struct MapPriorOptions {
  // The lexicon prior of a floor box read against the texts placed near it: the map paints
  // those texts there, so "some other text" is a ten times weaker hypothesis than against the
  // whole lexicon. 0 would force every box onto a text placed there. Chosen on the val split
  // among 0.05 / 0.005 / 0.0005 / 0, trading misreadings against false detections called
  // parking numbers (docs/OCR.md).
  LexiconOptions placed_lexicon = [] {
    LexiconOptions o;
    o.open_world_weight = 0.005;
    return o;
  }();
  // ... and of one whose centre lies on a text placed there (its footprint on the floor grown
  // by on_placed_text_margin_m): the map paints that text under the box, so "some other text"
  // is fifty times weaker again, and a faint reading of it (down to e^-5 a character) still
  // counts. Chosen on the val split (docs/OCR.md).
  LexiconOptions on_placed_text_lexicon = [] {
    LexiconOptions o;
    o.open_world_weight = 0.0001;
    o.min_log_prob_per_char = -5.0;
    return o;
  }();
  // Metres around a placed text's footprint within which a box lies on it (negative: never).
  double on_placed_text_margin_m = 0.1;
  // A floor box whose reading axis lies within this angle (radians) of the way the texts
  // placed near it read is read that way round only: half the recognizer's work, and no
  // reading of the number upside down ("600" for "009") to compete with the right one.
  double placed_reading_max_angle = 30.0 * M_PI / 180.0;
  // A floor box is classified under the class weights the texts placed near it give
  // (floorClassWeightsNear): a parking number only where the map paints one, and beside one,
  // other floor text at this weight (1: the classifier decides alone). Chosen on the val split
  // among 0 / 0.05 / 0.2 / 0.5 (docs/OCR.md).
  float unplaced_class_weight = 0.2f;
  // A floor box that may run out of the image decodes against the parts of the texts placed
  // near it that a cut would leave, of at least this many characters and half the text
  // (ocr/cut_parts.h; TextInstance::partial); 0: none.
  int min_cut_part_chars = 2;
  // A floor box read as a text placed near it is held to that text's size on the floor
  // (ocr/placed_size.h), because DB's unclip margin grows boxes of small text: tightened when
  // too tall or long, refused as that text when far too short; one that matched nothing, lying
  // on a text, is tightened too, or dropped as a fragment of it. Empty: never.
  std::optional<PlacedSizeOptions> placed_size = PlacedSizeOptions{};
};

}  // namespace parkloc::ocr
