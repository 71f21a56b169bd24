#include "ocr/classifier_training.h"

#include "io/polygon_points.h"
#include "io/sequence.h"
#include "ocr/training_data_files.h"

namespace parkloc::ocr {

ClassifierSamples collectClassifierSamples(const std::vector<std::string>& sequence_dirs,
                                           const SampleOptions& options) {
  ClassifierSamples out;
  std::vector<cv::Mat> rows;
  for (size_t s = 0; s < sequence_dirs.size(); ++s) {
    const io::Sequence sequence(sequence_dirs[s]);
    for (const size_t f :
         sampledFrames(sequence, options.frame_stride, options.max_frames_per_sequence)) {
      for (const auto& camera : sequence.cameras()) {
        const auto labels = sequence.loadLabels(f, camera);
        if (!labels || labels->instances.empty()) continue;
        const cv::Mat image = loadBgrImage(sequence, f, camera);
        if (image.empty()) continue;
        for (const auto& inst : labels->instances) {
          if (inst.occluded_fraction >= options.max_occluded_fraction || inst.truncated ||
              !inst.legible)
            continue;
          const Quad quad = io::pointQuad(inst.polygon);
          if (quadHeight(quad) < 4.f || quadWidth(quad) < 4.f) continue;
          for (const bool unread : {false, true}) {
            if (!givesSample(options.text, unread)) continue;
            rows.push_back(
                classifierFeatures(image, quad, unread ? "" : inst.text, options.features));
            out.labels.push_back(inst.cls);
            out.unread.push_back(unread);
          }
        }
      }
    }
    if (options.progress) options.progress(s + 1, sequence_dirs.size());
  }
  if (!rows.empty()) cv::vconcat(rows, out.features);
  return out;
}

double ClassifierScore::classAccuracy(map::TextClass c) const {
  const int t = static_cast<int>(c);
  const size_t total = confusion[t][0] + confusion[t][1] + confusion[t][2];
  return total ? double(confusion[t][t]) / total : 0.0;
}

ClassifierScore scoreClassifier(const TextClassifier& classifier, const ClassifierSamples& samples,
                                std::optional<bool> unread) {
  ClassifierScore score;
  for (int i = 0; i < samples.features.rows; ++i) {
    if (unread && samples.unread[i] != *unread) continue;
    const auto predicted = classifier.predict(samples.features.row(i)).first;
    const int t = static_cast<int>(samples.labels[i]), p = static_cast<int>(predicted);
    ++score.confusion[t][p];
    ++score.samples;
    if (t == p) ++score.correct;
  }
  return score;
}

}  // namespace parkloc::ocr
