// libFuzzer target: the configuration YAML of --config (config::parseConfig, yaml-cpp).
// A parsed configuration must write out as YAML that reads back to the same configuration.
#include "config/config.h"
#include "fuzz_support.h"

// One input: parse, then check the result against the contract.
static void fuzzOne(const uint8_t* data, size_t size) {
  using parkloc::fuzz::check;
  const std::string text(reinterpret_cast<const char*>(data), size);
  parkloc::config::Config config;
  if (!parkloc::fuzz::acceptsOnlyInputError(
          [&] { config = parkloc::config::parseConfig(text, "fuzz"); }))
    return;
  const std::string dumped = parkloc::config::dumpConfig(config);
  parkloc::config::Config again;
  check(parkloc::fuzz::acceptsOnlyInputError(
            [&] { again = parkloc::config::parseConfig(dumped, "dump"); }),
        "the dump of a parsed configuration does not parse");
  check(parkloc::config::dumpConfig(again) == dumped, "dump + parse changes the configuration");
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  parkloc::fuzz::withoutDescriptorLeak([&] { fuzzOne(data, size); });
  return 0;
}
