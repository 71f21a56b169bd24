#pragma once
// One spotter shared by the frame set's critical path and the search worker
// (search_worker.h) when the worker has none of its own: ocr::TextSpotter keeps per-call
// state, so the calls take turns behind a mutex. Correct, but the critical path then waits
// for the worker's full frame: a worker spotter of its own is what keeps the path short.
#include <mutex>
#include <string>
#include <vector>

#include "ocr/text_spotter.h"

namespace parkloc::localize {

class SerializedSpotter : public ocr::TextSpotter {
 public:
  // `inner` must outlive this.
  explicit SerializedSpotter(ocr::TextSpotter* inner) : inner_(inner) {}
  std::string name() const override { return inner_->name(); }
  std::vector<ocr::TextInstance> spot(const cv::Mat& image,
                                      const ocr::SpotRequest& request) override {
    std::lock_guard<std::mutex> lock(mutex_);
    return inner_->spot(image, request);
  }

 private:
  ocr::TextSpotter* inner_;
  std::mutex mutex_;
};

}  // namespace parkloc::localize
