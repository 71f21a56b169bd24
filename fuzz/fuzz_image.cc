// libFuzzer target: decoding a camera frame the way a drive is read. The bytes become the
// one image of a one-frame sequence folder and io::Sequence::loadImage decodes it (the file
// name says .jpg, but OpenCV picks the decoder from the content, as for a real frame, so
// every codec OpenCV was built with is reachable). The result must be empty with a reason,
// or an 8-bit 3-channel image of positive size.
#include <filesystem>
#include <fstream>
#include <memory>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "fuzz_support.h"
#include "geometry/rig.h"
#include "io/calibration_yaml.h"
#include "io/map_geojson.h"
#include "io/sequence.h"

namespace {

namespace fs = std::filesystem;

constexpr const char* kCamera = "front";

struct OneFrameSequence {
  fs::path dir;
  fs::path image;
  std::unique_ptr<parkloc::io::Sequence> sequence;

  OneFrameSequence()
      : dir("/dev/shm/parkloc-fuzz-" + std::to_string(::getpid()) + "-sequence"),
        image(dir / "images" / kCamera / "0.000000.jpg") {
    fs::remove_all(dir);
    fs::create_directories(image.parent_path());
    parkloc::io::saveCalibration(parkloc::geometry::defaultRig(), (dir / "calib.yaml").string());
    parkloc::io::saveMap(parkloc::map::HdMap(), (dir / "map.geojson").string());
    cv::imwrite(image.string(), cv::Mat(4, 4, CV_8UC3, cv::Scalar(1, 2, 3)));
    sequence = std::make_unique<parkloc::io::Sequence>(dir.string());
    parkloc::fuzz::check(sequence->timestamps().size() == 1, "set-up: expected one frame");
  }
  ~OneFrameSequence() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

// Built once, before the first input, so that its allocations are not counted as leaks.
std::unique_ptr<OneFrameSequence> g_frame;

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  g_frame = std::make_unique<OneFrameSequence>();
  return 0;
}

// One input: parse, then check the result against the contract.
static void fuzzOne(const uint8_t* data, size_t size) {
  using parkloc::fuzz::check;
  const OneFrameSequence& frame = *g_frame;
  {
    std::ofstream out(frame.image, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  cv::Mat image;
  std::string why;
  parkloc::fuzz::acceptsOnlyInputError(
      [&] { image = frame.sequence->loadImage(0, kCamera, &why); });
  if (image.empty()) {
    check(!why.empty(), "an empty image without a reason");
    return;
  }
  check(why.empty(), "a decoded image with a failure reason");
  check(image.type() == CV_8UC3, "decoded image is not 8-bit 3-channel");
  check(image.rows > 0 && image.cols > 0, "decoded image has no pixels");
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  parkloc::fuzz::withoutDescriptorLeak([&] { fuzzOne(data, size); });
  return 0;
}
