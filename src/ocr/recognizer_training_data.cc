#include "ocr/recognizer_training_data.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>

#include "common/error.h"
#include "io/polygon_points.h"
#include "io/sequence.h"
#include "ocr/ppocr/pp_ocr_networks.h"
#include "ocr/quad.h"
#include "ocr/training_data_files.h"

namespace parkloc::ocr {
namespace {

namespace fs = std::filesystem;

bool inAlphabet(const std::string& text, const std::string& alphabet) {
  if (text.empty()) return false;
  if (alphabet.empty()) return true;
  return std::all_of(text.begin(), text.end(),
                     [&](char c) { return alphabet.find(c) != std::string::npos; });
}

// The true quad grown, shifted and with its corners moved, all in the text's own rectified
// frame (so "height" means the text's height at any perspective), like a detector's box.
Quad jitteredQuad(const Quad& truth, const RecognizerDataOptions& o, std::mt19937_64& rng) {
  const float w = std::max(quadWidth(truth), 1.f), h = std::max(quadHeight(truth), 1.f);
  const cv::Mat to_rect = rectifyingHomography(truth, static_cast<int>(std::lround(w)),
                                               static_cast<int>(std::lround(h)));
  auto uniform = [&](double lo, double hi) {
    return std::uniform_real_distribution<>(lo, hi)(rng);
  };
  const double gx = uniform(1.0, o.max_grow_x), gy = uniform(1.0, o.max_grow_y);
  const double cx = 0.5 * w + uniform(-o.max_shift, o.max_shift) * h;
  const double cy = 0.5 * h + uniform(-o.max_shift, o.max_shift) * h;
  const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
  Quad rect;
  for (int k = 0; k < 4; ++k) {
    const double jx = uniform(-o.max_corner_jitter, o.max_corner_jitter) * h;
    const double jy = uniform(-o.max_corner_jitter, o.max_corner_jitter) * h;
    rect[k] = cv::Point2f(static_cast<float>(cx + sx[k] * 0.5 * gx * w + jx),
                          static_cast<float>(cy + sy[k] * 0.5 * gy * h + jy));
  }
  return transformQuad(rect, to_rect.inv());
}

void checkOptions(const RecognizerDataOptions& o) {
  if (o.out_dir.empty()) throw InputError("recognizer data: no output folder given");
  if (o.variants < 1 || o.other_class_variants < 0)
    throw InputError(fmt::format("recognizer data: variants = {}, other-class variants = {}",
                                 o.variants, o.other_class_variants));
  if (!(o.max_grow_x >= 1.0 && o.max_grow_y >= 1.0))
    throw InputError("recognizer data: box growth must be at least 1");
  if (!(o.max_shift >= 0.0 && o.max_corner_jitter >= 0.0))
    throw InputError("recognizer data: shifts must not be negative");
}

}  // namespace

RecognizerDataStats writeRecognizerTrainingData(const std::vector<std::string>& sequence_dirs,
                                                const RecognizerDataOptions& options) {
  checkOptions(options);
  const fs::path root(options.out_dir);
  createDirectory(root / "crops");
  const fs::path index_path = root / "index.tsv";
  std::ofstream index(index_path);
  if (!index) throw IoError(index_path.string() + ": cannot write");

  std::mt19937_64 rng(options.seed);
  RecognizerDataStats stats;
  for (size_t s = 0; s < sequence_dirs.size(); ++s) {
    const io::Sequence sequence(sequence_dirs[s]);
    const std::string name = sequenceName(sequence.dir());
    for (const size_t f :
         sampledFrames(sequence, options.frame_stride, options.max_frames_per_sequence)) {
      for (const auto& camera : sequence.cameras()) {
        const auto labels = sequence.loadLabels(f, camera);
        if (!labels) continue;
        cv::Mat raw;
        const std::string stem =
            fmt::format("{}_{}_{}", name, camera, io::timestampStem(sequence.timestamps()[f]));
        int n = 0;
        for (const auto& inst : labels->instances) {
          if (!inst.legible || inst.truncated ||
              inst.occluded_fraction >= options.max_occluded_fraction ||
              !inAlphabet(inst.text, options.alphabet))
            continue;
          if (raw.empty()) {
            raw = loadBgrImage(sequence, f, camera);
            if (raw.empty()) break;
          }
          const Quad truth = io::pointQuad(inst.polygon);
          const auto characters = static_cast<float>(inst.text.size());
          if (quadWidth(truth) < options.min_width_per_char * quadHeight(truth) * characters)
            continue;
          ++stats.texts;
          const int variants = inst.cls == map::TextClass::kParkingNumber
                                   ? options.variants
                                   : options.other_class_variants;
          for (int v = 0; v < variants; ++v) {
            // The first variant is the true box, the others as a detector might draw it.
            const Quad quad = v == 0 ? truth : jitteredQuad(truth, options, rng);
            const cv::Mat crop = rectifiedCrop(raw, quad, CtcRecognizer::kHeight,
                                               CtcRecognizer::kMinWidth, CtcRecognizer::kMaxWidth);
            const std::string rel = fmt::format("crops/{}_{}.png", stem, n++);
            writeImage(root / rel, crop);
            index << rel << '\t' << inst.text << '\t' << static_cast<int>(inst.cls) << '\n';
            ++stats.crops;
          }
        }
      }
    }
    if (options.progress) options.progress(s + 1, sequence_dirs.size());
  }
  index.flush();
  if (!index) throw IoError(index_path.string() + ": cannot write");
  return stats;
}

}  // namespace parkloc::ocr
