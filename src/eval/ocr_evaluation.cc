#include "eval/ocr_evaluation.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>

#include "eval/conditions.h"
#include "eval/dataset.h"
#include "eval/latency.h"
#include "eval/number_recall.h"
#include "eval/pose_prediction.h"
#include "io/sequence.h"

namespace parkloc::eval {

OcrEvaluation evaluateOcr(const std::vector<std::string>& sequences, ocr::TextSpotter& spotter,
                          const OcrRunOptions& options) {
  OcrEvaluator evaluator(options.metrics);
  NumberRecallTally frame_sets(options.metrics), drives(options.metrics);
  for (size_t s = 0; s < sequences.size(); ++s) {
    const io::Sequence seq(sequences[s]);
    const std::vector<std::string> conditions =
        sequenceConditions(seq.metaJson(), seq.dir() + "/meta.json");
    ocr::SpotRequest request;
    if (options.use_lexicon) {
      request.lexicon = map::distinctTexts(seq.map());
      request.floor_lexicon = map::distinctTexts(seq.map(), /*floor_only=*/true);
    }
    size_t frames = seq.timestamps().size();
    if (options.max_frames_per_sequence) frames = std::min(frames, options.max_frames_per_sequence);
    const std::string name = std::filesystem::path(seq.dir()).filename().string();
    const std::string stage = fmt::format("sequence {}/{} {}", s + 1, sequences.size(), name);
    std::optional<PosePrediction> prediction;
    if (const auto it = options.estimated_poses.find(name);
        options.use_lexicon && it != options.estimated_poses.end())
      prediction.emplace(it->second, seq.odometry());
    request.placement_radius_m = options.placement_radius_m;
    for (size_t i = 0; i < frames; ++i) {
      request.placed_floor_texts.clear();
      if (prediction)
        if (const auto pose = prediction->at(seq.timestamps()[i]))
          request.placed_floor_texts =
              map::placeFloorTexts(seq.map(), *pose, options.placement_range_m, "");
      for (const std::string& camera : seq.cameras()) {
        const std::optional<io::ImageLabels> labels = seq.loadLabels(i, camera);
        if (!labels) continue;  // no ground truth: nothing to score
        const cv::Mat image = seq.loadImage(i, camera);
        if (image.empty()) continue;
        request.camera = seq.rig().find(camera);  // the floor view needs the camera
        const auto start = std::chrono::steady_clock::now();
        const std::vector<ocr::TextInstance> found = spotter.spot(image, request);
        evaluator.add(*labels, found, conditions, msSince(start) / 1000.0);
        frame_sets.addImage(*labels, found);
        drives.addImage(*labels, found);
        if (options.on_image) options.on_image(name, *labels, found);
      }
      frame_sets.endGroup();
      if (options.progress) options.progress({stage, i + 1, frames});
    }
    drives.endGroup();
  }
  OcrEvaluation out = evaluator.result();
  out.parking_numbers_per_frame_set = frame_sets.result();
  out.parking_numbers_per_drive = drives.result();
  return out;
}

}  // namespace parkloc::eval
