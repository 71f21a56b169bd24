// Speed of the PP-OCRv4 engine on 2 intra-op threads: detection per camera image (raw
// 1280x800 at two input sizes, and the bird's-eye floor view), recognition per crop, and
// whole-image spotting (full frame and map-guided regions) of a rendered fisheye frame.
#include <benchmark/benchmark.h>

#include <opencv2/imgproc.hpp>

#include "../tests/ocr/synthetic_text.h"
#include "geometry/rig.h"
#include "ocr/ppocr/pp_ocr_networks.h"
#include "ocr/ppocr/pp_ocr_spotter.h"

namespace {

using namespace parkloc;

const std::string kModels = PARKLOC_MODEL_DIR;

// A 1280x800 left-camera frame with two floor numbers, and their true polygons.
struct Frame {
  cv::Mat image;
  std::vector<ocr::Quad> truths;
};

const Frame& frame() {
  static const Frame f = [] {
    const auto rig = geometry::defaultRig();
    const auto* left = rig.find("left");
    auto a = ocr::testing::renderFloorText(*left, "B2-117", {2.0, 2.6}, M_PI, 1.2, 0.45);
    auto b = ocr::testing::renderFloorText(*left, "B2-118", {4.6, 2.8}, M_PI, 1.2, 0.45);
    Frame out;
    cv::max(a.image, b.image, out.image);
    out.truths = {a.truth, b.truth};
    return out;
  }();
  return f;
}

void BM_DetectionRaw(benchmark::State& state) {
  const ocr::DbDetector detector(kModels + "/ch_PP-OCRv4_det_infer.onnx", {});
  const int w = static_cast<int>(state.range(0)), h = w * 800 / 1280 / 32 * 32;
  cv::Mat input;
  cv::resize(frame().image, input, {w, h}, 0, 0, cv::INTER_AREA);
  for (auto _ : state) benchmark::DoNotOptimize(detector.probability({input}));
  state.SetLabel(std::to_string(w) + "x" + std::to_string(h));
}
BENCHMARK(BM_DetectionRaw)->Arg(960)->Arg(640)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_DetectionGroundView(benchmark::State& state) {
  const ocr::DbDetector detector(kModels + "/ch_PP-OCRv4_det_infer.onnx", {});
  const auto rig = geometry::defaultRig();
  const ocr::GroundView view(*rig.find("left"));
  for (auto _ : state) benchmark::DoNotOptimize(detector.probability({view.render(frame().image)}));
  state.SetLabel(std::to_string(view.size().width) + "x" + std::to_string(view.size().height) +
                 " incl. remap");
}
BENCHMARK(BM_DetectionGroundView)->Unit(benchmark::kMillisecond)->UseRealTime();

// Under a predicted pose, the windows around texts placed beyond the floor view
// (ocr/placed_windows.h): the mosaic of Arg windows of 2.4 m, detected in one run, against
// BM_DetectionGroundView's whole view.
void BM_DetectionPlacedWindows(benchmark::State& state) {
  const ocr::DbDetector detector(kModels + "/ch_PP-OCRv4_det_infer.onnx", {});
  const auto rig = geometry::defaultRig();
  const auto* left = rig.find("left");
  const ocr::GroundView view(*left), reach(*left, ocr::PpOcrOptions{}.placed_reach);
  std::vector<map::PlacedText> placed;
  for (int k = 0; k < state.range(0); ++k) {  // 2.7 m apart along the left camera's row
    map::PlacedText text;
    text.text = "B2-" + std::to_string(120 + k);
    text.vehicle_xy = {2.0 + (k % 2 == 0 ? 1 : -1) * (6.9 + 2.7 * (k / 2)), 3.0};
    placed.push_back(text);
  }
  ocr::PlacedWindowOptions options;
  options.max_texts = 0;
  const auto windows = ocr::windowsBeyondView(view, reach, placed, options);
  cv::Size size;
  for (auto _ : state) {
    const auto mosaic = ocr::mosaicOf(reach, frame().image, windows);
    size = mosaic.image.size();
    benchmark::DoNotOptimize(detector.probability({mosaic.image}));
  }
  state.SetLabel(std::to_string(windows.size()) + " windows, " + std::to_string(size.width) + "x" +
                 std::to_string(size.height) + " incl. remap");
}
BENCHMARK(BM_DetectionPlacedWindows)
    ->Arg(1)
    ->Arg(2)
    ->Arg(4)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_RecognitionPerCrop(benchmark::State& state) {
  const ocr::CtcRecognizer recognizer(kModels + "/ch_PP-OCRv4_rec_infer.onnx", {});
  const int batch = static_cast<int>(state.range(0));
  const cv::Mat crop = ocr::rectifiedCrop(frame().image, frame().truths[0], 48, 16, 480);
  cv::Mat resized;
  cv::resize(crop, resized, {160, 48});
  const std::vector<cv::Mat> crops(batch, resized);
  for (auto _ : state) benchmark::DoNotOptimize(recognizer.recognize(crops, batch));
  state.SetItemsProcessed(state.iterations() * batch);
  state.SetLabel("48x160 crops, batch " + std::to_string(batch));
}
BENCHMARK(BM_RecognitionPerCrop)
    ->Arg(1)
    ->Arg(4)
    ->Arg(8)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

ocr::PpOcrSpotter& spotter(ocr::FisheyeView view) {
  static std::map<ocr::FisheyeView, std::unique_ptr<ocr::PpOcrSpotter>> cache;
  auto& s = cache[view];
  if (!s) {
    ocr::PpOcrOptions options;
    options.models = ocr::PpOcrModelPaths::inDirectory(kModels);
    options.view = view;
    s = std::make_unique<ocr::PpOcrSpotter>(options);
  }
  return *s;
}

void BM_SpotFullFrame(benchmark::State& state) {
  const auto view = static_cast<ocr::FisheyeView>(state.range(0));
  const auto rig = geometry::defaultRig();
  ocr::SpotRequest request;
  request.camera = rig.find("left");
  request.lexicon = {"B2-117", "B2-118", "B2-119"};
  auto& s = spotter(view);
  size_t found = 0;
  for (auto _ : state) found = s.spot(frame().image, request).size();
  const char* names[] = {"raw", "ground", "ground+raw"};
  state.SetLabel(std::string(names[state.range(0)]) + ", found " + std::to_string(found));
}
BENCHMARK(BM_SpotFullFrame)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// What `parkloc ocr --camera` runs by default: the fine-tuned floor detector and both class
// heads (read and unread) on top of PaddleOCR's recognizer, with parkloc's tuned recognizer
// for second opinions (this frame's number needs none; docs/OCR.md gives their cost on the
// test split).
void BM_SpotFullFrameShipped(benchmark::State& state) {
  static const auto shipped = [] {
    ocr::PpOcrOptions options;
    options.models = ocr::PpOcrModelPaths::inDirectory(kModels);
    options.models.floor_detection = ocr::floorDetectorIn(kModels);
    options.models.fallback_recognition = ocr::tunedRecognizerIn(kModels);
    options.models.classifier = std::string(PARKLOC_SOURCE_DIR) + "/models/text_classifier.yml";
    options.models.unread_classifier =
        std::string(PARKLOC_SOURCE_DIR) + "/models/text_classifier_unread.yml";
    return std::make_unique<ocr::PpOcrSpotter>(options);
  }();
  const auto rig = geometry::defaultRig();
  ocr::SpotRequest request;
  request.camera = rig.find("left");
  request.lexicon = {"B2-117", "B2-118", "B2-119"};
  size_t found = 0;
  for (auto _ : state) found = shipped->spot(frame().image, request).size();
  state.SetLabel("ground, tuned floor detector, class heads, second opinions, found " +
                 std::to_string(found));
}
BENCHMARK(BM_SpotFullFrameShipped)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SpotRegions(benchmark::State& state) {
  const auto rig = geometry::defaultRig();
  ocr::SpotRequest request;
  request.camera = rig.find("left");
  for (const auto& t : frame().truths) {
    ocr::RegionOfInterest r;
    for (int k = 0; k < 4; ++k) r.polygon[k] = t[k] + cv::Point2f(6, -4);
    r.expected_texts = {"B2-117", "B2-118"};
    request.regions.push_back(r);
  }
  auto& s = spotter(ocr::FisheyeView::kGroundAndRaw);
  size_t found = 0;
  for (auto _ : state) found = s.spot(frame().image, request).size();
  state.SetLabel("2 regions, found " + std::to_string(found));
}
BENCHMARK(BM_SpotRegions)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
