#pragma once
// The spotters a configuration asks for: the critical path's, and the workers' own
// (localize/search_worker.h), each worker's with the workers' inference threads.
#include <memory>

#include "config/config.h"
#include "localize/search_worker.h"
#include "ocr/text_spotter.h"

namespace parkloc::config {

// The critical path's spotter, with the configuration's inference threads.
std::unique_ptr<ocr::TextSpotter> makeSpotter(const Config& config);

// A spotter only for each worker the configuration runs (none in paper mode). Made after
// makeSpotter's, whose thread counts size ONNX Runtime's shared pool.
struct WorkerSpotterSet {
  std::unique_ptr<ocr::TextSpotter> search, reads;
  localize::WorkerSpotters pointers() const { return {search.get(), reads.get()}; }
};
WorkerSpotterSet makeWorkerSpotters(const Config& config);

}  // namespace parkloc::config
