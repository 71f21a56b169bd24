#include "ocr/onnx_model.h"

#include <onnxruntime_cxx_api.h>

#include <filesystem>
#include <numeric>

#include "common/error.h"

namespace parkloc::ocr {
namespace {

// One process-wide environment (ONNX Runtime allows a single Ort::Env per process), with
// the shared thread pool sized by the first model loaded.
struct Environment {
  OnnxOptions pool;
  Ort::Env env;

  explicit Environment(const OnnxOptions& first)
      : pool(first), env(threading(first), ORT_LOGGING_LEVEL_ERROR, "parkloc") {}

  static Ort::ThreadingOptions threading(const OnnxOptions& options) {
    Ort::ThreadingOptions threading;
    threading.SetGlobalIntraOpNumThreads(options.intra_op_threads);
    threading.SetGlobalInterOpNumThreads(options.inter_op_threads);
    return threading;
  }
  bool shares(const OnnxOptions& options) const {
    return options.intra_op_threads == pool.intra_op_threads &&
           options.inter_op_threads == pool.inter_op_threads;
  }
};

// Never destroyed, on purpose: destroying it at exit joins the pool's threads after the exit
// handlers have already freed ONNX Runtime's own statics made during the first Run (static
// destruction runs in reverse order of construction), and ASan once caught a pool thread
// reading one of them. Left alive, the idle threads touch nothing while the
// process ends; the pointer stays reachable, so it is no leak to LeakSanitizer.
Environment& environment(const OnnxOptions& first) {
  static Environment* const environment = new Environment(first);
  return *environment;
}

}  // namespace

struct OnnxModel::Impl {
  std::unique_ptr<Ort::Session> session;
  std::string input_name;
  std::string output_name;
};

OnnxModel::OnnxModel(const std::string& path, const OnnxOptions& options)
    : path_(path), impl_(std::make_unique<Impl>()) {
  if (!std::filesystem::is_regular_file(path)) throw IoError("model file not found: " + path);
  try {
    Environment& environment = ocr::environment(options);
    Ort::SessionOptions session_options;
    if (environment.shares(options)) {
      session_options.DisablePerSessionThreads();
    } else {
      session_options.SetIntraOpNumThreads(options.intra_op_threads);
      session_options.SetInterOpNumThreads(options.inter_op_threads);
      session_options.AddConfigEntry("session.intra_op.allow_spinning", "0");
    }
    session_options.SetGraphOptimizationLevel(GraphOptimizationLevel::ORT_ENABLE_ALL);
    impl_->session = std::make_unique<Ort::Session>(environment.env, path.c_str(), session_options);
    Ort::AllocatorWithDefaultOptions allocator;
    impl_->input_name = impl_->session->GetInputNameAllocated(0, allocator).get();
    impl_->output_name = impl_->session->GetOutputNameAllocated(0, allocator).get();
  } catch (const Ort::Exception& e) {
    throw InputError("cannot load ONNX model " + path + ": " + e.what());
  }
}

OnnxModel::~OnnxModel() = default;
OnnxModel::OnnxModel(OnnxModel&&) noexcept = default;
OnnxModel& OnnxModel::operator=(OnnxModel&&) noexcept = default;

Tensor OnnxModel::run(const Tensor& input) const {
  const auto memory = Ort::MemoryInfo::CreateCpu(OrtArenaAllocator, OrtMemTypeDefault);
  // ONNX Runtime takes a non-const pointer but does not write to inputs.
  auto* data = const_cast<float*>(input.data.data());
  Ort::Value in = Ort::Value::CreateTensor<float>(memory, data, input.data.size(),
                                                  input.shape.data(), input.shape.size());
  const char* input_names[] = {impl_->input_name.c_str()};
  const char* output_names[] = {impl_->output_name.c_str()};
  auto outputs =
      impl_->session->Run(Ort::RunOptions{nullptr}, input_names, &in, 1, output_names, 1);
  const auto info = outputs[0].GetTensorTypeAndShapeInfo();
  Tensor out;
  out.shape = info.GetShape();
  const size_t count = info.GetElementCount();
  const float* values = outputs[0].GetTensorData<float>();
  out.data.assign(values, values + count);
  return out;
}

}  // namespace parkloc::ocr
