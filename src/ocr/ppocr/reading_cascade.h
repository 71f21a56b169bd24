#pragma once
// The reading cascade: every read job's rectified crop goes through the recognizer, and what
// no lexicon entry fits is read again, each step costing only the jobs still unmatched:
//   1. direction: the direction classifier decides which way round a crop reads, and only
//      when it is unsure are both turns read (DirectionMode);
//   2. first reads, CTC decoded against the job's lexicon (ocr/lexicon.h) and freely;
//   3. the other direction, where the classifier was sure yet nothing matched;
//   4. the fallback recognizer (a second opinion: only its lexicon matches count);
//   5. rereads of an unmatched placed box from crops with larger margins.
// Each job keeps its best reading.
#include <limits>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ocr/ctc.h"
#include "ocr/lexicon.h"
#include "ocr/ppocr/pp_ocr_models.h"
#include "ocr/ppocr/read_jobs.h"

namespace parkloc::ocr {

enum class DirectionMode {
  kDecodeBoth,  // recognize the 0 and 180 degree crops, keep the better reading
  kClassifier,  // the direction classifier decides; both only when it is unsure
};

// Margins for ReadingOptions::reread_margins (along, across the text): larger than the floor
// boxes' own (DetectionOptions::floor_read_expand_x/y), so a crop that cut into the glyphs
// gets them whole. A second, tight margin (1.0 x 1.1) reads 1.4 points more on the test split
// for 12 ms more an image, too close to the 100 ms budget (docs/OCR.md).
inline const std::vector<std::pair<float, float>> kRereadMargins = {{1.25f, 1.7f}};

struct ReadingOptions {
  // Crops are CtcRecognizer::kHeight px tall and at most this wide (wider ones are squeezed).
  int max_crop_width = CtcRecognizer::kMaxWidth;
  int batch_size = 8;  // crops per recognizer run
  DirectionMode direction = DirectionMode::kClassifier;
  float direction_confident = 0.9f;  // classifier probability above which one crop suffices
  // The lexicon prior of a job without a prior of its own (ReadJob::prior).
  LexiconOptions lexicon;
  // A crop read with a lexicon (the map's texts) is read freely, too, with only these
  // characters and the lexicon's (ctcGreedyDecode): the garage's script, not the 6625
  // classes of a Chinese recognizer. Empty, or a job without a lexicon: every class.
  std::string alphabet = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ";
  // Free readings (no lexicon match) below this mean confidence are dropped as non-text,
  // unless the detector is sure of the box (ReadJob::keep_unread).
  float min_text_confidence = 0.6f;
  // A floor box read against the texts placed near it, one way round, that no reading
  // matched is read again from crops grown by each of these factors (along, across the text),
  // its matches counting as the first reading's: DB's box may cut into a glyph the map says
  // is there. Empty: none.
  std::vector<std::pair<float, float>> reread_margins = kRereadMargins;
  // ... by the fallback recognizer alone (by the first when there is none), its matches
  // second opinions: the first recognizer already failed on that box, and reading it again
  // costs time for little gain (docs/OCR.md).
  bool reread_by_fallback_only = true;
};

// A job's best reading.
struct JobReading {
  double score = -std::numeric_limits<double>::infinity();
  LexiconDecoding decoding;
  bool turned = false;          // read from the crop turned by 180 degrees
  bool second_opinion = false;  // read by the fallback recognizer
};

// Reads every job through the cascade. `fallback`: the second recognizer, null for none.
std::vector<JobReading> readJobs(const cv::Mat& image, const std::vector<ReadJob>& jobs,
                                 const ReadingOptions& options, const PpOcrModels& models,
                                 const CtcRecognizer* fallback);

// Whether a reading names a text: a lexicon match, or a confident free reading.
bool namesAText(const LexiconDecoding& decoding, const ReadingOptions& options);

// The instance a job's reading makes, when the job is reported (it names a text, or the
// detector is sure of its box); its polygon is the job's quad as it reads, not yet refined.
std::optional<TextInstance> instanceOf(const ReadJob& job, const JobReading& reading,
                                       const ReadingOptions& options);

// The classes a free reading may use: those of `base` and of every character of the lexicon
// that the charset has (a text with a character it lacks cannot be matched anyway). Throws
// InputError for a character of `base` the charset lacks.
std::vector<int> freeReadingClasses(const std::string& base,
                                    const std::vector<std::string>& lexicon,
                                    const Charset& charset);

}  // namespace parkloc::ocr
