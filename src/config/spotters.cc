#include "config/spotters.h"

#include <algorithm>

#include "ocr/ppocr/pp_ocr_spotter.h"

namespace parkloc::config {

std::unique_ptr<ocr::TextSpotter> makeSpotter(const Config& config) {
  return std::make_unique<ocr::PpOcrSpotter>(spotterOptions(config));
}

WorkerSpotterSet makeWorkerSpotters(const Config& config) {
  const localize::RealtimeOptions& realtime = config.pipeline.realtime;
  WorkerSpotterSet out;
  if (config.pipeline.paper_mode) return out;
  ocr::PpOcrOptions options = spotterOptions(config);
  // With one thread all of a worker's inference runs on its own thread, at its priority.
  options.onnx.intra_op_threads = std::max(1, realtime.worker_inference_threads);
  if (realtime.background_search) out.search = std::make_unique<ocr::PpOcrSpotter>(options);
  if (realtime.background_reads) out.reads = std::make_unique<ocr::PpOcrSpotter>(options);
  return out;
}

}  // namespace parkloc::config
