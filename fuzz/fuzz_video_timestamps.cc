// libFuzzer target: a video's capture-time CSV (io::loadVideoTimestamps). Rows must have frame
// indices and finite timestamps that both strictly increase.
#include <cmath>

#include "fuzz_support.h"
#include "io/video_timestamps.h"

static void fuzzOne(const uint8_t* data, size_t size) {
  using parkloc::fuzz::check;
  static const parkloc::fuzz::ScratchFile input("timestamps.csv");
  const std::string& path = input.write(data, size);
  std::vector<parkloc::io::VideoFrameTime> rows;
  if (!parkloc::fuzz::acceptsOnlyInputError(
          [&] { rows = parkloc::io::loadVideoTimestamps(path); }))
    return;
  check(!rows.empty(), "no rows accepted");
  for (size_t i = 0; i < rows.size(); ++i) {
    check(rows[i].frame >= 0 && std::isfinite(rows[i].timestamp), "bad row accepted");
    check(i == 0 || (rows[i].frame > rows[i - 1].frame &&
                     rows[i].timestamp > rows[i - 1].timestamp),
          "rows not increasing");
  }
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  parkloc::fuzz::withoutDescriptorLeak([&] { fuzzOne(data, size); });
  return 0;
}
