#pragma once
// A thin wrapper over one ONNX Runtime Ort::Session with one float input and one float output,
// which is all the PP-OCR models need. Keeps ONNX Runtime out of every other header.
#include <memory>
#include <string>
#include <vector>

namespace parkloc::ocr {

// Thread counts of a model's Ort::Session. The first model loaded sizes one process-wide thread
// pool, and every model with the same counts runs on it: the models of a spotter run one
// after the other, and pools of their own kept spinning after each run and took the cores
// from the next model (full-frame spotting 114-117 ms with a pool per model, 80-93 ms with
// one). A model with other counts gets a pool of its own that sleeps when idle.
struct OnnxOptions {
  int intra_op_threads = 2;
  int inter_op_threads = 1;
};

// A float tensor in row-major order.
struct Tensor {
  std::vector<int64_t> shape;
  std::vector<float> data;
};

class OnnxModel {
 public:
  // Throws InputError naming the path when the file is missing or not a loadable model.
  OnnxModel(const std::string& path, const OnnxOptions& options = {});
  ~OnnxModel();
  OnnxModel(OnnxModel&&) noexcept;
  OnnxModel& operator=(OnnxModel&&) noexcept;

  const std::string& path() const { return path_; }
  // Runs the model on `input` (shape and data); returns its first output.
  Tensor run(const Tensor& input) const;

 private:
  struct Impl;
  std::string path_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace parkloc::ocr
