#include "ocr/ppocr/pp_ocr_spotter.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <opencv2/imgproc.hpp>
#include <optional>

#include "common/error.h"
#include "ocr/cut_parts.h"
#include "ocr/placed_classes.h"
#include "ocr/ppocr/pp_ocr_networks.h"

namespace parkloc::ocr {

PpOcrModelPaths PpOcrModelPaths::inDirectory(const std::string& dir) {
  PpOcrModelPaths paths;
  paths.detection = dir + "/ch_PP-OCRv4_det_infer.onnx";
  paths.recognition = dir + "/ch_PP-OCRv4_rec_infer.onnx";
  paths.direction = dir + "/ch_ppocr_mobile_v2.0_cls_infer.onnx";
  paths.dictionary = dir + "/ppocr_keys_v1.txt";
  return paths;
}

void requireBgrImage(const cv::Mat& image, const std::string& what) {
  if (image.empty()) throw InputError(what + ": empty image");
  if (image.type() != CV_8UC3)
    throw InputError(what + ": expected an 8-bit 3-channel (BGR) image, got type " +
                     std::to_string(image.type()) + " with " + std::to_string(image.channels()) +
                     " channels");
}

struct PpOcrSpotter::Networks {
  DbDetector detector;
  std::optional<DbDetector> floor_detector;  // empty: `detector` serves the floor view too
  std::optional<DbDetector> band_detector;   // empty: no band detection
  CtcRecognizer recognizer;
  std::optional<DirectionClassifier> direction;
  Charset charset;
  TextClassifier classifier;
  TextClassifier unread_classifier;  // empty: `classifier` classifies unread boxes too
  std::optional<CtcRecognizer> fallback_recognizer;  // empty: none

  // The class head for an instance: the unread head when nothing was read.
  const TextClassifier& headFor(const TextInstance& instance) const {
    return instance.text.empty() && !unread_classifier.empty() ? unread_classifier : classifier;
  }
};

namespace {

int roundTo32(double v) { return std::max(32, static_cast<int>(std::lround(v / 32.0)) * 32); }

// The classes a free reading may use: those of `base` and of every character of the lexicon
// that the charset has (a text with a character it lacks cannot be matched anyway). Throws
// InputError for a character of `base` the charset lacks.
std::vector<int> freeReadingClasses(const std::string& base,
                                    const std::vector<std::string>& lexicon,
                                    const Charset& charset) {
  std::string alphabet = base;
  for (const auto& text : lexicon)
    for (const auto& ch : splitUtf8(text))
      if (alphabet.find(ch) == std::string::npos && charset.encode(ch)) alphabet += ch;
  return charset.readingClasses(alphabet);
}

// One quad to read: where it is, which texts it may be, whether to try it upside down.
struct ReadJob {
  Quad quad;
  float detection_score = 0.f;
  const std::vector<std::string>* lexicon = nullptr;
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

}  // namespace

PpOcrSpotter::PpOcrSpotter(const PpOcrOptions& options) : options_(options) {
  const auto& m = options.models;
  nets_ = std::unique_ptr<Networks>(new Networks{
      DbDetector(m.detection, options.onnx), std::nullopt, std::nullopt,
      CtcRecognizer(m.recognition, options.onnx), std::nullopt,
      Charset::fromDictionaryFile(m.dictionary), TextClassifier(), TextClassifier(), std::nullopt});
  freeReadingClasses(options.reading_alphabet, {}, nets_->charset);  // a foreign character throws
  if (!m.floor_detection.empty()) nets_->floor_detector.emplace(m.floor_detection, options.onnx);
  if (!m.band_detection.empty()) {
    checkBand(options.band);
    nets_->band_detector.emplace(m.band_detection, options.onnx);
  }
  if (!m.direction.empty()) nets_->direction.emplace(m.direction, options.onnx);
  if (!m.fallback_recognition.empty())
    nets_->fallback_recognizer.emplace(m.fallback_recognition, options.onnx);
  if (!m.classifier.empty()) nets_->classifier = TextClassifier::load(m.classifier);
  if (!m.unread_classifier.empty())
    nets_->unread_classifier = TextClassifier::load(m.unread_classifier);
}

PpOcrSpotter::~PpOcrSpotter() = default;

std::vector<TextInstance> PpOcrSpotter::spot(const cv::Mat& image, const SpotRequest& request) {
  requireBgrImage(image);
  return request.regions.empty() ? spotFullFrame(image, request) : spotRegions(image, request);
}

namespace {

// The refined corners when they are plausible (plausibleRefinement), else the box.
Quad refinedCorners(const cv::Mat& image, const Quad& quad, const PpOcrOptions& options,
                    const geometry::RigCamera* camera) {
  if (!options.refine_corners) return quad;
  std::optional<Quad> refined;
  if (camera != nullptr) refined = refineOnGround(image, quad, *camera, options.refinement);
  if (!refined) refined = refineInCrop(image, quad, options.refinement);
  return refined && plausibleRefinement(quad, *refined, options.refinement) ? *refined : quad;
}

// Reads every job: rectified crops (and their 180 degree turns where the direction is in
// doubt) go through the recognizer in batches; each job keeps its better direction.
std::vector<std::optional<TextInstance>> readJobs(
    const cv::Mat& image, const std::vector<ReadJob>& jobs, const geometry::RigCamera* camera,
    const PpOcrOptions& options, const CtcRecognizer& recognizer,
    const DirectionClassifier* direction, const Charset& charset,
    const CtcRecognizer* fallback_recognizer = nullptr) {
  auto firstReads = [&](size_t i) {
    return !jobs[i].fallback_only || fallback_recognizer == nullptr;
  };
  std::vector<cv::Mat> upright(jobs.size());
  for (size_t i = 0; i < jobs.size(); ++i)
    upright[i] = rectifiedCrop(
        image, expandQuad(jobs[i].quad, jobs[i].read_expand_x, jobs[i].read_expand_y),
        CtcRecognizer::kHeight, CtcRecognizer::kMinWidth, options.recognition_max_width);

  // Which directions to decode, per job: bit 0 upright, bit 1 turned.
  std::vector<int> directions(jobs.size(), 1);
  std::vector<float> upside_down(jobs.size(), 0.f);
  if (options.direction == DirectionMode::kClassifier && direction != nullptr) {
    std::vector<cv::Mat> ask;
    std::vector<size_t> asked;
    for (size_t i = 0; i < jobs.size(); ++i)
      if (jobs[i].try_both_directions && firstReads(i)) {
        ask.push_back(upright[i]);
        asked.push_back(i);
      }
    const auto p = direction->upsideDownProbability(ask);
    for (size_t k = 0; k < asked.size(); ++k) {
      const float conf = options.direction_confident;
      directions[asked[k]] = p[k] >= conf ? 2 : p[k] <= 1.f - conf ? 1 : 3;
    }
  } else {
    for (size_t i = 0; i < jobs.size(); ++i)
      if (jobs[i].try_both_directions) directions[i] = 3;
  }

  CropBatch first;
  for (size_t i = 0; i < jobs.size(); ++i) {
    if (!firstReads(i)) continue;
    if (directions[i] & 1) first.add(upright[i], i, false);
    if (directions[i] & 2) first.add(upright[i], i, true);
  }
  static const std::vector<std::string> kNoLexicon;
  struct Best {
    double score = -std::numeric_limits<double>::infinity();
    LexiconDecoding decoding;
    bool turned = false;
    bool second_opinion = false;  // read by the fallback recognizer
  };
  std::vector<Best> best(jobs.size());
  // The free reading's classes per lexicon (the jobs of a request share one or a few).
  std::vector<std::pair<const std::vector<std::string>*, std::vector<int>>> classes_of;
  auto readingClasses = [&](const std::vector<std::string>* lexicon) -> std::vector<int> {
    if (lexicon == nullptr || lexicon->empty() || options.reading_alphabet.empty()) return {};
    for (const auto& [key, classes] : classes_of)
      if (key == lexicon) return classes;
    classes_of.emplace_back(lexicon,
                            freeReadingClasses(options.reading_alphabet, *lexicon, charset));
    return classes_of.back().second;
  };
  // The fallback recognizer (second_opinion) contributes lexicon matches only.
  auto decodeAll = [&](const CropBatch& batch, const CtcRecognizer& reader, bool second_opinion) {
    if (batch.crops.empty()) return;
    const auto outputs = reader.recognize(batch.crops, options.recognition_batch);
    for (size_t k = 0; k < outputs.size(); ++k) {
      const auto [job, turned] = batch.owner[k];
      const auto& lexicon = jobs[job].lexicon ? *jobs[job].lexicon : kNoLexicon;
      const auto* reading_lexicon =
          jobs[job].reading_lexicon ? jobs[job].reading_lexicon : jobs[job].lexicon;
      LexiconDecoding d =
          decodeWithLexicon(outputs[k].matrix(), charset, lexicon,
                            jobs[job].onPlacedText() ? options.on_placed_text_lexicon
                            : jobs[job].placed       ? options.placed_lexicon
                                                     : options.lexicon,
                            readingClasses(reading_lexicon));
      if (second_opinion && !d.matched) continue;
      // Both directions share the crop's step count, so their log probabilities compare;
      // a lexicon match beats a free reading.
      const double score = (d.matched ? 1e6 : 0.0) +
                           (d.matched ? std::max(d.best_log_prob, d.raw_log_prob) : d.raw_log_prob);
      if (score > best[job].score) best[job] = {score, std::move(d), turned, second_opinion};
    }
  };
  decodeAll(first, recognizer, false);
  // A job with a lexicon that none of its readings so far matches.
  auto unmatched = [&](size_t i) {
    return jobs[i].lexicon != nullptr && !jobs[i].lexicon->empty() && !best[i].decoding.matched;
  };

  // The direction classifier was sure, yet no lexicon entry fits: try the other direction.
  CropBatch retry;
  for (size_t i = 0; i < jobs.size(); ++i)
    if (directions[i] != 3 && jobs[i].try_both_directions && unmatched(i) && firstReads(i))
      retry.add(upright[i], i, directions[i] == 1);
  decodeAll(retry, recognizer, false);

  // What no lexicon entry fits, the fallback recognizer reads both ways round; only its
  // lexicon matches count.
  if (fallback_recognizer != nullptr) {
    CropBatch again;
    for (size_t i = 0; i < jobs.size(); ++i) {
      if (!unmatched(i)) continue;
      again.add(upright[i], i, false);
      if (jobs[i].try_both_directions) again.add(upright[i], i, true);
    }
    decodeAll(again, *fallback_recognizer, true);
  }

  // A box read against the texts placed near it, one way round, that nothing matched yet is
  // read again from crops with other margins, by the fallback recognizer (and the first, unless
  // PpOcrOptions::reread_by_fallback_only).
  CropBatch margins;
  for (size_t i = 0; i < jobs.size(); ++i) {
    if (!unmatched(i) || !jobs[i].placed || jobs[i].try_both_directions || !firstReads(i)) continue;
    for (const auto& [along, across] : options.reread_margins)
      margins.add(
          rectifiedCrop(image, expandQuad(jobs[i].quad, along, across), CtcRecognizer::kHeight,
                        CtcRecognizer::kMinWidth, options.recognition_max_width),
          i, false);
  }
  if (fallback_recognizer == nullptr || !options.reread_by_fallback_only)
    decodeAll(margins, recognizer, false);
  if (fallback_recognizer != nullptr) decodeAll(margins, *fallback_recognizer, true);

  std::vector<std::optional<TextInstance>> out(jobs.size());
  for (size_t i = 0; i < jobs.size(); ++i) {
    const Best& b = best[i];
    const LexiconDecoding& d = b.decoding;
    const bool read =
        d.matched || (!d.raw_text.empty() && d.raw_confidence >= options.min_text_confidence);
    if (!read && !jobs[i].keep_unread) continue;
    TextInstance inst;
    inst.polygon = refinedCorners(image, b.turned ? shiftedBy180(jobs[i].quad) : jobs[i].quad,
                                  options, camera);
    inst.raw_text = d.raw_text;
    inst.lexicon_match = d.matched;
    inst.second_opinion = d.matched && b.second_opinion;
    inst.text = d.matched ? (*jobs[i].lexicon)[d.best_index] : read ? d.raw_text : "";
    if (d.matched && jobs[i].cut != nullptr) {
      inst.text = jobs[i].cut->whole[d.best_index];
      inst.partial = jobs[i].cut->texts[d.best_index] != inst.text;
    }
    // A confident free reading of a box on a placed text that is one end of that text, glyph
    // for glyph, is that text partly seen.
    if (!d.matched && read && jobs[i].onPlacedText() && options.min_cut_part_chars > 0) {
      const CutCandidates parts = withCutParts(*jobs[i].placed_near, true, true,
                                               static_cast<size_t>(options.min_cut_part_chars));
      if (const auto whole = wholeOfPart(d.raw_text, parts)) {
        inst.text = *whole;
        inst.lexicon_match = inst.partial = true;
      }
    }
    inst.recognition_score = d.matched ? static_cast<float>(d.posterior) : d.raw_confidence;
    inst.detection_score = jobs[i].detection_score;
    out[i] = std::move(inst);
  }
  return out;
}

}  // namespace

struct PpOcrSpotter::FloorWindow {
  const GroundView* view = nullptr;
  const WindowMosaic* mosaic = nullptr;  // the image is this mosaic of `view`; null: `view`
  // Read only the boxes near a placed text, and keep only those that match one.
  bool only_placed_texts = false;

  // What to add to the image pixels of what lies at `p` to get `view` pixels; empty in a gap
  // between windows.
  std::optional<cv::Point2f> shiftAt(const cv::Point2f& p) const {
    return mosaic != nullptr ? mosaic->shiftAt(p) : cv::Point2f(0.f, 0.f);
  }
  // Whether a quad (reading order, shifted by `shift` into the view) may run out of what the
  // camera sees at its start and at its end: a point a quarter of its length beyond that end is
  // not in the image (pixel centres 0 .. size - 1) or lies behind the vehicle's body.
  std::pair<bool, bool> mayRunOutOfSight(const Quad& quad, const cv::Point2f& shift) const {
    const cv::Point2f start = 0.5f * (quad[0] + quad[3]), end = 0.5f * (quad[1] + quad[2]);
    const cv::Point2f beyond = 0.25f * (end - start);
    return {!view->seesTheFloorAt(start - beyond + shift),
            !view->seesTheFloorAt(end + beyond + shift)};
  }
};

const GroundView& PpOcrSpotter::groundView(const geometry::RigCamera& camera) {
  // Keyed by the whole calibration, not the name: two rigs may both have a "left" camera.
  for (const auto& view : ground_views_)
    if (geometry::sameCalibration(view->camera(), camera)) return *view;
  ground_views_.push_back(std::make_unique<GroundView>(camera, options_.ground_view));
  return *ground_views_.back();
}

const GroundView& PpOcrSpotter::placedReach(const geometry::RigCamera& camera) {
  for (const auto& view : placed_reaches_)
    if (geometry::sameCalibration(view->camera(), camera)) return *view;
  GroundViewOptions reach = options_.placed_reach;
  reach.resolution = options_.ground_view.resolution;  // what the floor detector was tuned at
  placed_reaches_.push_back(std::make_unique<GroundView>(camera, reach));
  return *placed_reaches_.back();
}

std::vector<TextInstance> PpOcrSpotter::detectAndRead(const cv::Mat& image,
                                                      const SpotRequest& request,
                                                      const geometry::RigCamera* camera,
                                                      DetectorRole role, const FloorWindow* floor) {
  // A floor view's scale is its resolution, chosen for the floor detector: a view wider than
  // detection_max_side (+-8 m at 1.5 cm) is not shrunk.
  const double fit =
      role == DetectorRole::kRawBand || role == DetectorRole::kFloorView
          ? 1.0
          : std::min(1.0, options_.detection_max_side / double(std::max(image.cols, image.rows)));
  const double scale = fit * std::clamp(static_cast<double>(request.detection_scale), 0.1, 1.0);
  const int w = roundTo32(image.cols * scale), h = roundTo32(image.rows * scale);
  cv::Mat resized;
  if (w == image.cols && h == image.rows)
    resized = image;
  else
    cv::resize(image, resized, {w, h}, 0, 0, cv::INTER_AREA);
  const DbDetector* detector = &nets_->detector;
  const DbOptions* db = &options_.db;
  float read_expand_x = 1.f, read_expand_y = 1.f;  // the tuned floor detector's boxes only
  if (role == DetectorRole::kFloorView && nets_->floor_detector) {
    detector = &*nets_->floor_detector;
    db = &options_.floor_db;
    read_expand_x = options_.floor_read_expand_x;
    read_expand_y = options_.floor_read_expand_y;
  } else if (role == DetectorRole::kRawBand && nets_->band_detector) {
    detector = &*nets_->band_detector;
    db = &options_.band_db;
  }
  const cv::Mat probability = detector->probability({resized})[0];
  const float sx = float(image.cols) / probability.cols, sy = float(image.rows) / probability.rows;

  std::vector<DbBox> boxes = dbBoxesFromProbability(probability, *db);
  for (DbBox& box : boxes)  // map pixels -> image pixels
    for (auto& p : box.quad) p = {(p.x + 0.5f) * sx - 0.5f, (p.y + 0.5f) * sy - 0.5f};
  if (request.max_reads > 0 && boxes.size() > static_cast<size_t>(request.max_reads)) {
    // Under a read budget the confident boxes go first: the weaker ones that a low box
    // threshold lets through are read only when the budget has room left.
    std::vector<DbBox> first;
    for (size_t i : readingPriority(boxes, options_.confident_box_score)) {
      if (first.size() == static_cast<size_t>(request.max_reads)) break;
      first.push_back(boxes[i]);
    }
    boxes = std::move(first);
  }
  // Under a predicted pose each floor box decodes against the texts placed near it; the
  // jobs point into `placed_lexicons`.
  const FloorWindow* placing =
      role == DetectorRole::kFloorView && floor != nullptr && !request.placed_floor_texts.empty()
          ? floor
          : nullptr;
  std::deque<std::vector<std::string>> placed_lexicons;
  std::deque<CutCandidates> cut_lexicons;
  std::vector<ReadJob> jobs;
  for (const DbBox& box : boxes) {
    ReadJob job;
    job.quad = box.quad;
    job.detection_score = box.score;
    job.lexicon = role == DetectorRole::kFloorView && !request.floor_lexicon.empty()
                      ? &request.floor_lexicon
                      : &request.lexicon;
    if (placing != nullptr) {
      const std::optional<cv::Point2f> shift = placing->shiftAt(quadCentre(box.quad));
      if (!shift) continue;
      const Eigen::Vector2d ground = placing->view->groundFromView(quadCentre(box.quad) + *shift);
      const double radius = request.placement_radius_m;
      std::vector<std::string> near = map::textsNear(request.placed_floor_texts, ground, radius);
      // A window beyond the view looks for the texts placed in it, not at what lies around
      // them (a parked car's edges): nothing else there is read.
      if (placing->only_placed_texts && near.empty()) continue;
      if (request.narrow_to_placed_texts) {
        placed_lexicons.push_back(std::move(near));
        job.reading_lexicon = job.lexicon;
        job.lexicon = &placed_lexicons.back();
        job.placed = true;
        if (options_.on_placed_text_margin_m >= 0.0 &&
            map::placedTextUnder(request.placed_floor_texts, ground,
                                 options_.on_placed_text_margin_m) != nullptr)
          job.placed_near = job.lexicon;
      }
      // The texts placed there say which way round the box reads.
      const auto reading = map::readingDirectionNear(request.placed_floor_texts, ground, radius,
                                                     options_.placed_reading_max_angle);
      if (reading) {
        const cv::Point2f along = placing->view->viewFromGround(ground + *reading) -
                                  placing->view->viewFromGround(ground);
        if (const auto oriented =
                orientedAlong(job.quad, along, options_.placed_reading_max_angle)) {
          job.quad = *oriented;
          job.try_both_directions = false;
        }
      }
      // A box that may be a number cut by the image border or the vehicle's body also decodes
      // against the parts of the texts placed there that the cut would leave (only when it reads
      // one way round: the cut end must be known).
      if (request.narrow_to_placed_texts && !job.try_both_directions &&
          options_.min_cut_part_chars > 0 && !job.lexicon->empty()) {
        const auto [at_start, at_end] = placing->mayRunOutOfSight(job.quad, *shift);
        if (at_start || at_end) {
          cut_lexicons.push_back(withCutParts(*job.lexicon, at_start, at_end,
                                              static_cast<size_t>(options_.min_cut_part_chars)));
          job.cut = &cut_lexicons.back();
          job.lexicon = &job.cut->texts;
        }
      }
    }
    job.keep_unread = role == DetectorRole::kFloorView && box.score >= options_.confident_box_score;
    job.read_expand_x = read_expand_x;
    job.read_expand_y = read_expand_y;
    job.fallback_only = placing != nullptr && placing->only_placed_texts;
    jobs.push_back(job);
  }
  const CtcRecognizer* fallback = nets_->fallback_recognizer && request.second_opinions
                                      ? &*nets_->fallback_recognizer
                                      : nullptr;
  auto read = readJobs(image, jobs, camera, options_, nets_->recognizer,
                       nets_->direction ? &*nets_->direction : nullptr, nets_->charset, fallback);
  std::vector<TextInstance> out;
  for (auto& r : read)
    if (r) out.push_back(std::move(*r));
  return out;
}

namespace {

bool contains(const Quad& quad, const cv::Point2f& p) {
  return cv::pointPolygonTest(std::vector<cv::Point2f>(quad.begin(), quad.end()), p, false) >= 0;
}

// Whether `inst`'s centre lies in the polygon of one of the first `count` of `found`.
bool seenBefore(const TextInstance& inst, const std::vector<TextInstance>& found, size_t count) {
  const cv::Point2f c = quadCentre(inst.polygon);
  for (size_t i = 0; i < count; ++i)
    if (contains(found[i].polygon, c)) return true;
  return false;
}

// Holds a floor box read as a text placed near it, or lying on one, to that text's size
// (PpOcrOptions::placed_size), in `view`'s pixels, which keep the floor's proportions. A box
// refused as that text loses its reading; false when it is then not confident enough to be
// reported unread, or read nothing and is a fragment of the text it lies on.
bool holdToPlacedSize(TextInstance& inst, const GroundView& view, const SpotRequest& request,
                      const PlacedSizeOptions& size, float confident_box_score) {
  const std::optional<Quad> in_view = view.viewFromRaw(inst.polygon);
  if (!in_view) return true;  // a corner off the floor: no size to compare
  const Eigen::Vector2d centre = view.groundFromView(quadCentre(*in_view));
  // A box read as a text is held to the nearest text of that name, one nothing matched to the
  // text it lies on.
  const map::PlacedText* placed =
      inst.lexicon_match ? map::nearestPlaced(request.placed_floor_texts, centre,
                                              request.placement_radius_m, inst.text)
      : size.unmatched_margin_m >= 0.0
          ? map::placedTextUnder(request.placed_floor_texts, centre, size.unmatched_margin_m)
          : nullptr;
  if (placed == nullptr) return true;
  const double resolution = view.options().resolution;
  const float width = static_cast<float>(placed->width / resolution),
              height = static_cast<float>(placed->height / resolution);
  const PlacedSizeFit fit =
      inst.lexicon_match
          ? fitToPlacedSize(*in_view, width, height, !inst.partial, size)
          : fitUnmatchedToPlacedSize(*in_view, width, height,
                                     view.viewFromGround(centre + placed->reading.normalized()) -
                                         view.viewFromGround(centre),
                                     size);
  if (fit.verdict == PlacedSize::kRefused) {
    if (!inst.lexicon_match) return false;  // a fragment of the text it lies on
    inst.text.clear();
    inst.lexicon_match = inst.second_opinion = inst.partial = false;
    inst.recognition_score = 0.f;
    return inst.detection_score >= confident_box_score;
  }
  if (fit.verdict == PlacedSize::kTightened) {
    if (const auto in_raw = view.rawFromView(fit.quad)) {
      inst.polygon = *in_raw;
      inst.sized_by_map = true;
    }
  }
  return true;
}

}  // namespace

std::vector<TextInstance> PpOcrSpotter::spotFullFrame(const cv::Mat& image,
                                                      const SpotRequest& request) {
  const bool ground = options_.view != FisheyeView::kRaw && request.camera != nullptr &&
                      request.camera->model.width == image.cols &&
                      request.camera->model.height == image.rows;
  std::vector<TextInstance> out;
  size_t on_floor = 0;                      // out[0, on_floor) came from the floor view
  std::vector<ClassWeights> floor_classes;  // their class weights
  const bool placed_classes = request.narrow_to_placed_texts && !request.placed_floor_texts.empty();
  // Floor text found and read in a bird's-eye view (or a mosaic of its windows), its corners
  // mapped back to raw; with `skip_seen`, text whose centre lies in a polygon found before is
  // dropped.
  auto addFloorText = [&](const cv::Mat& rendered, const FloorWindow& window, bool skip_seen) {
    const size_t found_before = out.size();
    for (TextInstance& inst :
         detectAndRead(rendered, request, nullptr, DetectorRole::kFloorView, &window)) {
      // A window reports the placed texts it was opened for, not what else it read.
      if (window.only_placed_texts && !inst.lexicon_match) continue;
      const std::optional<cv::Point2f> shift = window.shiftAt(quadCentre(inst.polygon));
      if (!shift) continue;
      const ClassWeights weights =
          placed_classes ? floorClassWeightsNear(
                               request.placed_floor_texts,
                               window.view->groundFromView(quadCentre(inst.polygon) + *shift),
                               request.placement_radius_m, options_.unplaced_class_weight)
                         : kFloorClasses;
      Quad in_view = inst.polygon;
      for (auto& p : in_view) p += *shift;
      const std::optional<Quad> in_raw = window.view->rawFromView(in_view);
      if (!in_raw) continue;
      inst.polygon = *in_raw;
      if (skip_seen && seenBefore(inst, out, found_before)) continue;
      // Final corner fit at the raw image's resolution, on the ground plane.
      inst.polygon = refinedCorners(image, inst.polygon, options_, request.camera);
      if (placed_classes && options_.placed_size &&
          !holdToPlacedSize(inst, *window.view, request, *options_.placed_size,
                            options_.confident_box_score))
        continue;
      out.push_back(std::move(inst));
      floor_classes.push_back(weights);
    }
  };
  if (ground) {
    const GroundView& view = groundView(*request.camera);
    addFloorText(view.render(image), {&view, nullptr, false}, false);
    if (request.look_beyond_the_view && !request.placed_floor_texts.empty() &&
        options_.placed_reach.half_width > 0) {
      const GroundView& reach = placedReach(*request.camera);
      const WindowMosaic mosaic = mosaicOf(
          reach, image,
          windowsBeyondView(view, reach, request.placed_floor_texts, options_.placed_windows));
      if (!mosaic.image.empty()) addFloorText(mosaic.image, {&reach, &mosaic, true}, true);
    }
    on_floor = out.size();
  }
  // Raw-image detections already found (their centre inside a polygon found before) are
  // dropped.
  auto addUnseen = [&](std::vector<TextInstance> found) {
    const size_t found_before = out.size();
    for (TextInstance& inst : found)
      if (!seenBefore(inst, out, found_before)) out.push_back(std::move(inst));
  };
  if (ground && nets_->band_detector) {
    // The horizon band at full resolution; its crops are read from the band itself (a view
    // of the image, not a copy), corners fitted in the crop (pillar text is not on the floor).
    const cv::Rect rows = bandRect(options_.band, image.size());
    std::vector<TextInstance> found =
        detectAndRead(image(rows), request, nullptr, DetectorRole::kRawBand);
    for (TextInstance& inst : found)
      for (auto& p : inst.polygon) p.y += static_cast<float>(rows.y);
    addUnseen(std::move(found));
  }
  if (!ground || options_.view == FisheyeView::kGroundAndRaw)
    addUnseen(detectAndRead(image, request, request.camera, DetectorRole::kScene));
  for (size_t i = 0; i < out.size(); ++i) {
    TextInstance& inst = out[i];
    const auto [cls, score] = nets_->headFor(inst).classify(
        image, inst.polygon, inst.text, i < on_floor ? floor_classes[i] : kAnyClass);
    inst.cls = cls;
    inst.class_score = score;
  }
  return out;
}

std::vector<TextInstance> PpOcrSpotter::spotRegions(const cv::Mat& image,
                                                    const SpotRequest& request) {
  // Identified texts are only fitted; the others are detected and read.
  std::vector<TextInstance> out;
  SpotRequest to_read = request;
  to_read.regions.clear();
  for (const RegionOfInterest& region : request.regions) {
    if (region.read) {
      to_read.regions.push_back(region);
      continue;
    }
    if (region.expected_texts.empty()) continue;
    const auto fitted =
        fitTrackedText(image, region.predicted, request.camera, options_.tracked_fit);
    if (!fitted) continue;
    TextInstance inst;
    inst.polygon = *fitted;
    inst.text = region.expected_texts.front();
    inst.cls = region.expected_class;
    inst.read = false;
    out.push_back(std::move(inst));
  }
  if (to_read.regions.empty()) return out;
  for (TextInstance& inst : readRegions(image, to_read)) out.push_back(std::move(inst));
  return out;
}

std::vector<TextInstance> PpOcrSpotter::readRegions(const cv::Mat& image,
                                                    const SpotRequest& request) {
  // A region with the text's own predicted polygon is read right there (the lexicon must
  // vouch for it); the others are searched by the detector in a rectified patch.
  auto predicted = [&](const RegionOfInterest& r) {
    return options_.read_at_prediction && quadWidth(r.predicted) > 1.f &&
           quadHeight(r.predicted) > 1.f;
  };
  const cv::Size patch = options_.region_patch;
  const float aspect = float(patch.width) / patch.height;
  std::vector<cv::Mat> patches;
  std::vector<size_t> patch_region;
  std::vector<cv::Mat> patch_from_image;
  std::vector<std::pair<float, float>> text_size_in_patch;  // predicted w, h in patch pixels
  for (size_t r = 0; r < request.regions.size(); ++r) {
    if (predicted(request.regions[r])) continue;
    const Quad& q = request.regions[r].polygon;
    const float w = std::max(quadWidth(q), 1.f), h = std::max(quadHeight(q), 1.f);
    // The expanded region keeps the patch's aspect ratio, so the text is not stretched.
    const float expanded_h =
        std::max(h * options_.region_expand_y, w * options_.region_expand_x / aspect);
    const float expanded_w = expanded_h * aspect;
    const Quad expanded = expandQuad(q, expanded_w / w, expanded_h / h);
    cv::Mat H = rectifyingHomography(expanded, patch.width, patch.height);
    cv::Mat p;
    cv::warpPerspective(image, p, H, patch, cv::INTER_LINEAR, cv::BORDER_CONSTANT);
    patches.push_back(p);
    patch_region.push_back(r);
    patch_from_image.push_back(H);
    text_size_in_patch.emplace_back(w / expanded_w * patch.width, h / expanded_h * patch.height);
  }
  const auto maps = patches.empty() ? std::vector<cv::Mat>{} : nets_->detector.probability(patches);

  std::vector<ReadJob> jobs(request.regions.size());
  for (size_t r = 0; r < request.regions.size(); ++r) {
    jobs[r].lexicon = &request.regions[r].expected_texts;
    jobs[r].try_both_directions = false;  // the map predicts the reading direction
    jobs[r].quad = predicted(request.regions[r])
                       ? expandQuad(request.regions[r].predicted, options_.prediction_expand_x,
                                    options_.prediction_expand_y)
                       : request.regions[r].polygon;  // read the prediction itself; score 0
  }
  for (size_t k = 0; k < patches.size(); ++k) {
    // The detected box nearest the patch centre, where the map predicts the text.
    const cv::Point2f centre(patch.width * 0.5f, patch.height * 0.5f);
    const auto [tw, th] = text_size_in_patch[k];
    std::optional<DbBox> chosen;
    float chosen_cost = 0.f;
    for (const DbBox& box : dbBoxesFromProbability(maps[k], options_.db)) {
      const cv::Point2f c = quadCentre(box.quad);
      const float dx = (c.x - centre.x) / std::max(tw, 1.f),
                  dy = (c.y - centre.y) / std::max(th, 1.f);
      const float cost = dx * dx + dy * dy;
      if (std::abs(dx) > 0.75f || std::abs(dy) > 1.f) continue;
      if (!chosen || cost < chosen_cost) {
        chosen = box;
        chosen_cost = cost;
      }
    }
    if (chosen) {
      jobs[patch_region[k]].quad = transformQuad(chosen->quad, patch_from_image[k].inv());
      jobs[patch_region[k]].detection_score = chosen->score;
    }
  }
  auto read = readJobs(image, jobs, request.camera, options_, nets_->recognizer,
                       nets_->direction ? &*nets_->direction : nullptr, nets_->charset);
  std::vector<TextInstance> out;
  for (size_t r = 0; r < read.size(); ++r) {
    // A region where no text was detected counts only when the lexicon vouches for it.
    if (!read[r] || (jobs[r].detection_score == 0.f && !read[r]->lexicon_match)) continue;
    TextInstance& inst = *read[r];
    const auto [cls, score] = nets_->classifier.classify(image, inst.polygon, inst.text);
    inst.cls = cls;
    inst.class_score = score;
    out.push_back(std::move(inst));
  }
  return out;
}

}  // namespace parkloc::ocr
