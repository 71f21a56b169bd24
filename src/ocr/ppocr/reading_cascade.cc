#include "ocr/ppocr/reading_cascade.h"

#include <algorithm>
#include <limits>
#include <opencv2/imgproc.hpp>

namespace parkloc::ocr {

namespace {

// A reading score bonus larger than any gap between the log probabilities of two readings of
// one crop, so that any lexicon match outranks any free reading.
constexpr double kLexiconMatchBonus = 1e6;

// Which ways round a crop is decoded: a bit set.
enum Turns : int { kUpright = 1, kTurned = 2, kBothTurns = kUpright | kTurned };

// Crops for one recognizer call, each with its job and whether it was turned by 180 degrees.
struct CropBatch {
  std::vector<cv::Mat> crops;
  std::vector<std::pair<size_t, bool>> owner;  // job, turned

  void add(const cv::Mat& upright, size_t job, bool turned) {
    cv::Mat crop;  // a new image when turned: `upright` may be queued too
    if (turned)
      cv::rotate(upright, crop, cv::ROTATE_180);
    else
      crop = upright;
    crops.push_back(crop);
    owner.emplace_back(job, turned);
  }
};

// The cascade's state over one set of jobs: their crops, the turns to read, the best reading
// of each so far.
class Cascade {
 public:
  Cascade(const cv::Mat& image, const std::vector<ReadJob>& jobs, const ReadingOptions& options,
          const PpOcrModels& models, const CtcRecognizer* fallback)
      : image_(image),
        jobs_(jobs),
        options_(options),
        models_(models),
        fallback_(fallback),
        upright_(jobs.size()),
        turns_(jobs.size(), kUpright),
        best_(jobs.size()) {
    for (size_t i = 0; i < jobs.size(); ++i)
      upright_[i] = crop(expandQuad(jobs[i].quad, jobs[i].read_expand_x, jobs[i].read_expand_y));
  }

  std::vector<JobReading> run() {
    chooseTurns();
    readFirst();
    readOtherTurn();
    readByFallback();
    rereadWithMargins();
    return std::move(best_);
  }

 private:
  // Whether the first recognizer reads a job (a fallback-only job is read by the fallback).
  bool firstReads(size_t i) const { return !jobs_[i].fallback_only || fallback_ == nullptr; }
  // A job with a lexicon that none of its readings so far matches.
  bool unmatched(size_t i) const {
    return jobs_[i].lexicon != nullptr && !jobs_[i].lexicon->empty() && !best_[i].decoding.matched;
  }
  cv::Mat crop(const Quad& quad) const {
    return rectifiedCrop(image_, quad, CtcRecognizer::kHeight, CtcRecognizer::kMinWidth,
                         options_.max_crop_width);
  }

  // 1. The direction classifier says which way round each crop reads; where it is unsure, or
  // decides nothing, both turns are read.
  void chooseTurns() {
    if (options_.direction == DirectionMode::kClassifier && models_.direction) {
      std::vector<cv::Mat> ask;
      std::vector<size_t> asked;
      for (size_t i = 0; i < jobs_.size(); ++i)
        if (jobs_[i].try_both_directions && firstReads(i)) {
          ask.push_back(upright_[i]);
          asked.push_back(i);
        }
      const auto p = models_.direction->upsideDownProbability(ask);
      const float conf = options_.direction_confident;
      for (size_t k = 0; k < asked.size(); ++k)
        turns_[asked[k]] = p[k] >= conf ? kTurned : p[k] <= 1.f - conf ? kUpright : kBothTurns;
    } else {
      for (size_t i = 0; i < jobs_.size(); ++i)
        if (jobs_[i].try_both_directions) turns_[i] = kBothTurns;
    }
  }

  // 2. The first recognizer reads each crop the way(s) round chosen.
  void readFirst() {
    CropBatch first;
    for (size_t i = 0; i < jobs_.size(); ++i) {
      if (!firstReads(i)) continue;
      if (turns_[i] & kUpright) first.add(upright_[i], i, false);
      if (turns_[i] & kTurned) first.add(upright_[i], i, true);
    }
    decodeAll(first, models_.recognizer, false);
  }

  // 3. The direction classifier was sure, yet no lexicon entry fits: try the other direction.
  void readOtherTurn() {
    CropBatch retry;
    for (size_t i = 0; i < jobs_.size(); ++i)
      if (turns_[i] != kBothTurns && jobs_[i].try_both_directions && unmatched(i) && firstReads(i))
        retry.add(upright_[i], i, turns_[i] == kUpright);
    decodeAll(retry, models_.recognizer, false);
  }

  // 4. What no lexicon entry fits, the fallback recognizer reads both ways round; only its
  // lexicon matches count.
  void readByFallback() {
    if (fallback_ == nullptr) return;
    CropBatch again;
    for (size_t i = 0; i < jobs_.size(); ++i) {
      if (!unmatched(i)) continue;
      again.add(upright_[i], i, false);
      if (jobs_[i].try_both_directions) again.add(upright_[i], i, true);
    }
    decodeAll(again, *fallback_, true);
  }

  // 5. A box read against the texts placed near it, one way round, that nothing matched yet
  // is read again from crops with other margins, by the fallback recognizer (and the first,
  // unless ReadingOptions::reread_by_fallback_only).
  void rereadWithMargins() {
    CropBatch margins;
    for (size_t i = 0; i < jobs_.size(); ++i) {
      if (!unmatched(i) || !jobs_[i].placed || jobs_[i].try_both_directions || !firstReads(i))
        continue;
      for (const auto& [along, across] : options_.reread_margins)
        margins.add(crop(expandQuad(jobs_[i].quad, along, across)), i, false);
    }
    if (fallback_ == nullptr || !options_.reread_by_fallback_only)
      decodeAll(margins, models_.recognizer, false);
    if (fallback_ != nullptr) decodeAll(margins, *fallback_, true);
  }

  // The free reading's classes for a lexicon (the jobs of a request share one or a few).
  std::vector<int> readingClasses(const std::vector<std::string>* lexicon) {
    if (lexicon == nullptr || lexicon->empty() || options_.alphabet.empty()) return {};
    for (const auto& [key, classes] : classes_of_)
      if (key == lexicon) return classes;
    classes_of_.emplace_back(lexicon,
                             freeReadingClasses(options_.alphabet, *lexicon, models_.charset));
    return classes_of_.back().second;
  }

  // Decodes a batch's recognizer outputs, each job keeping its best reading. A second opinion
  // (the fallback recognizer) contributes lexicon matches only.
  void decodeAll(const CropBatch& batch, const CtcRecognizer& reader, bool second_opinion) {
    if (batch.crops.empty()) return;
    static const std::vector<std::string> kNoLexicon;
    const auto outputs = reader.recognize(batch.crops, options_.batch_size);
    for (size_t k = 0; k < outputs.size(); ++k) {
      const auto [i, turned] = batch.owner[k];
      const ReadJob& job = jobs_[i];
      const auto* reading_lexicon = job.reading_lexicon ? job.reading_lexicon : job.lexicon;
      LexiconDecoding d = decodeWithLexicon(
          outputs[k].matrix(), models_.charset, job.lexicon ? *job.lexicon : kNoLexicon,
          job.prior ? *job.prior : options_.lexicon, readingClasses(reading_lexicon));
      if (second_opinion && !d.matched) continue;
      // Both directions share the crop's step count, so their log probabilities compare.
      const double score = (d.matched ? kLexiconMatchBonus : 0.0) +
                           (d.matched ? std::max(d.best_log_prob, d.raw_log_prob) : d.raw_log_prob);
      if (score > best_[i].score) best_[i] = {score, std::move(d), turned, second_opinion};
    }
  }

  const cv::Mat& image_;
  const std::vector<ReadJob>& jobs_;
  const ReadingOptions& options_;
  const PpOcrModels& models_;
  const CtcRecognizer* fallback_;
  std::vector<cv::Mat> upright_;  // each job's crop as its quad reads
  std::vector<int> turns_;        // Turns to read, per job
  std::vector<JobReading> best_;
  std::vector<std::pair<const std::vector<std::string>*, std::vector<int>>> classes_of_;
};

}  // namespace

std::vector<int> freeReadingClasses(const std::string& base,
                                    const std::vector<std::string>& lexicon,
                                    const Charset& charset) {
  std::string alphabet = base;
  for (const auto& text : lexicon)
    for (const auto& ch : splitUtf8(text))
      if (alphabet.find(ch) == std::string::npos && charset.encode(ch)) alphabet += ch;
  return charset.readingClasses(alphabet);
}

std::vector<JobReading> readJobs(const cv::Mat& image, const std::vector<ReadJob>& jobs,
                                 const ReadingOptions& options, const PpOcrModels& models,
                                 const CtcRecognizer* fallback) {
  return Cascade(image, jobs, options, models, fallback).run();
}

bool namesAText(const LexiconDecoding& d, const ReadingOptions& options) {
  return d.matched || (!d.raw_text.empty() && d.raw_confidence >= options.min_text_confidence);
}

std::optional<TextInstance> instanceOf(const ReadJob& job, const JobReading& reading,
                                       const ReadingOptions& options) {
  const LexiconDecoding& d = reading.decoding;
  const bool read = namesAText(d, options);
  if (!read && !job.keep_unread) return std::nullopt;
  TextInstance inst;
  inst.polygon = reading.turned ? shiftedBy180(job.quad) : job.quad;
  inst.raw_text = d.raw_text;
  inst.lexicon_match = d.matched;
  inst.second_opinion = d.matched && reading.second_opinion;
  inst.text = d.matched ? (*job.lexicon)[d.best_index] : read ? d.raw_text : "";
  if (d.matched && job.cut != nullptr) {
    inst.text = job.cut->whole[d.best_index];
    inst.partial = job.cut->texts[d.best_index] != inst.text;
  }
  inst.recognition_score = d.matched ? static_cast<float>(d.posterior) : d.raw_confidence;
  inst.detection_score = job.detection_score;
  return inst;
}

}  // namespace parkloc::ocr
