// Replays the scenario inputs the fuzzer found (docs/RELIABILITY.md, finding 12): each must
// end in InputError, never in a yaml-cpp exception.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/error.h"
#include "sim/scenario.h"

namespace parkloc::sim {
namespace {

TEST(ScenarioFuzzRegression, EveryRecordedInputIsRejectedWithInputError) {
  const std::filesystem::path dir =
      std::filesystem::path(PARKLOC_SOURCE_DIR) / "tests/data/fuzz_regressions/scenario";
  int replayed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_THROW(parseScenario(text.str(), entry.path().filename().string()), InputError)
        << entry.path();
    ++replayed;
  }
  EXPECT_GE(replayed, 4);
}

}  // namespace
}  // namespace parkloc::sim
