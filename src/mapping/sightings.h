#pragma once
// Stage 1 of map building, reading: every text the spotter reads on every frame set of a
// drive, with no map to guide it (full frames, free reading, the floor view of each camera),
// as sightings: one camera's reading of one text at one frame set.
#include <Eigen/Core>
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "io/sequence.h"
#include "map/landmark.h"
#include "map/numbering.h"
#include "ocr/text_spotter.h"

namespace parkloc::mapping {

struct Sighting {
  size_t drive = 0;  // index of the drive among those the map is built from
  size_t frame = 0;  // frame set index within the drive
  int camera = -1;   // index into the drive's Rig::cameras
  std::string text;
  map::TextClass cls = map::TextClass::kParkingNumber;
  // Image corners in reading order (top-left, top-right, bottom-right, bottom-left).
  std::array<Eigen::Vector2d, 4> pixels;
  double recognition_score = 0.0;
  // Only the fallback recognizer matched the reading to the lexicon, after the first reader
  // matched nothing (ocr::TextInstance::second_opinion).
  bool second_opinion = false;
  // Read against a numbering's lexicon, it matched none of its numbers: a free reading.
  bool off_numbering = false;
  // No ink fit: the corners are the detector's box, padded around the glyphs by a margin
  // that varies with the font and the paint (ocr::TextInstance::box_only).
  bool box_only = false;
};

struct ReadingOptions {
  // Every this many frame sets is read (1: all); more frame sets, more sightings per text.
  int frame_step = 1;
  // A reading less probable than this (the recognizer's calibrated score) is no sighting: it
  // would only be outvoted in the consensus.
  double min_recognition_score = 0.5;
  // Learn the garage's numbering formats (map/numbering.h) from a first, free reading of every
  // `survey_step`-th frame set, then read the drive again against the numbers they span.
  // False: free reading only (and the formats the user gives, if any).
  bool learn_numbering = true;
  int survey_step = 3;
  map::NumberingOptions numbering;
  // ... and those the user knows, comma-separated ("C###,K2-###"; empty: none).
  std::string formats;
};

struct ReadingStats {
  size_t frame_sets = 0;  // frame sets read
  size_t images = 0;      // camera images spotted
  size_t missing_images = 0;
  size_t instances = 0;  // text instances the spotter returned
  double seconds = 0.0;  // wall time of the spotting, both readings
  // The first, free reading that learns the numbering (ReadingOptions::learn_numbering).
  size_t survey_frame_sets = 0;
  double survey_seconds = 0.0;
};

// Sightings of parking numbers (painted on the floor) in `drive`, every `frame_step`-th frame
// set; `lexicon` (may be empty: free reading) is what the spotter reads against, the strings
// of the garage's numbering formats. `progress` (may be empty) is told (done, total) frame
// sets.
std::vector<Sighting> readDrive(const io::Sequence& drive, size_t drive_index,
                                ocr::TextSpotter& spotter, int frame_step,
                                const std::vector<std::string>& lexicon,
                                const ReadingOptions& options, ReadingStats& stats,
                                const std::function<void(size_t, size_t)>& progress = {});

}  // namespace parkloc::mapping
