#pragma once
// Text spotting: every text instance of a camera image with its polygon, content, class
// and scores. Engines (PP-OCRv4 on ONNX Runtime, an oracle from labels, ...) implement
// TextSpotter; nothing outside src/ocr knows which engine runs.
#include <array>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "geometry/rig.h"
#include "map/landmark.h"
#include "map/placed_texts.h"

namespace parkloc::ocr {

struct TextInstance {
  // Image pixels, reading order: top-left, top-right, bottom-right, bottom-left of the
  // text as it reads (so an upside-down number has its top-left at the bottom right).
  std::array<cv::Point2f, 4> polygon;
  // The lexicon entry when one matched, else the raw reading when it is confident, else
  // empty: text the detector is sure of that nothing could read (see
  // DetectionOptions::confident_box_score).
  std::string text;
  std::string raw_text;  // greedy CTC reading
  bool lexicon_match = false;
  // The lexicon match came from the fallback recognizer alone (PpOcrModelPaths::
  // fallback_recognition), after the first reader matched nothing: a second opinion, which
  // the localization lets confirm a tracked pose but never start one.
  bool second_opinion = false;
  // The lexicon matched only the part of `text` that the image shows (a number cut by the
  // image border, read against the texts placed near it: SpotRequest::narrow_to_placed_texts):
  // `text` is the whole text, `polygon` spans the part.
  bool partial = false;
  // The box was tightened to the size the map gives the text it was read as (under a
  // predicted pose: MapPriorOptions::placed_size): its corners are not all the ink's.
  bool sized_by_map = false;
  // No ink fit was plausible (docs/OCR.md, "8. Corner refinement"): the corners are the
  // detector's box, which holds the text but whose size follows the detector's kernel.
  bool box_only = false;
  map::TextClass cls = map::TextClass::kOther;
  float detection_score = 0.f;
  float recognition_score = 0.f;  // calibrated probability of `text`
  float class_score = 0.f;
  // False when the corners were fitted where the map predicts an identified text, without
  // reading it (RegionOfInterest::read == false): `text` is then the expected text and the
  // scores are 0.
  bool read = true;
};

// A region where the map predicts text (map-guided spotting): the predicted polygon in
// the image and the texts expected there.
struct RegionOfInterest {
  std::array<cv::Point2f, 4> polygon;
  std::vector<std::string> expected_texts;
  // Tracking: false when the text was read in recent frames, so that only its
  // corners are fitted to the ink around `predicted` (the text's own projected polygon,
  // reading order), with no detection or recognition; the instance then carries
  // expected_texts.front() and `expected_class`.
  bool read = true;
  std::array<cv::Point2f, 4> predicted{};
  map::TextClass expected_class = map::TextClass::kOther;
};

struct SpotRequest {
  // Texts to decode against (CTC forward score); empty means free reading only.
  std::vector<std::string> lexicon;
  // The texts painted on the floor, when known: what an engine finds in a
  // bird's-eye view of the floor decodes against these instead, since upright text (pillars)
  // never shows there as text. Empty: such boxes decode against `lexicon` too.
  std::vector<std::string> floor_lexicon;
  // The floor texts around the vehicle under a predicted pose (map/placed_texts.h; added
  // later): a box found in the floor view then decodes against those placed within
  // `placement_radius_m` of its centre instead of all of `floor_lexicon` (none near: a free
  // reading), and is read only the way round they read (when they agree and the box lies along
  // them; MapPriorOptions::placed_reading_max_angle). Needs `camera`. Empty: no placement.
  std::vector<map::PlacedText> placed_floor_texts;
  // Half a bay: the centre of a box and of its text differ by the pose's error and, for a
  // number cut by the image border, by up to half its length.
  double placement_radius_m = 1.0;
  // True: such a box decodes against the texts placed near it and takes the class of one of
  // them (other floor text where none is: every parking number is in the map, not every mark
  // on the floor). False: it decodes against all of `floor_lexicon` and takes any floor class,
  // as without placement, the texts placed near it saying only which way round it reads
  // (MapPriorOptions::placed_reading_max_angle).
  // A box that may run out of the image then also decodes against the parts of those texts
  // that a cut would leave (ocr/cut_parts.h; TextInstance::partial).
  bool narrow_to_placed_texts = true;
  // Full frame, with `placed_floor_texts` and `camera`: also look for the floor texts placed
  // beyond the camera's floor view, in windows of a wider view around them (engines that
  // detect in a floor view; ocr/placed_windows.h).
  bool look_beyond_the_view = true;
  // When non-empty, spot only inside these regions instead of the full frame.
  std::vector<RegionOfInterest> regions;
  // The camera that took the image, when known (not owned): engines may use its
  // calibration, e.g. to fit floor text corners on the ground plane.
  const geometry::RigCamera* camera = nullptr;
  // Full frame: read at most this many detected boxes, the largest first (0: all). A
  // tracking vehicle sweeps the full frame only to catch what the map prediction missed,
  // within its real-time budget.
  int max_reads = 0;
  // Full frame: the detector's input is scaled by this (< 1: coarser and faster, for such a
  // sweep; large text only).
  float detection_scale = 1.f;
  // Full frame: have the engine's fallback recognizer, if it has one, read again what the
  // first matched to no lexicon entry (TextInstance::second_opinion).
  bool second_opinions = true;
};

class TextSpotter {
 public:
  virtual ~TextSpotter() = default;
  virtual std::string name() const = 0;
  // `image` is 8-bit BGR. Throws InputError for an empty or wrongly typed image.
  virtual std::vector<TextInstance> spot(const cv::Mat& image, const SpotRequest& request) = 0;
};

}  // namespace parkloc::ocr
