// parkloc config dump [--config FILE]: every option in effect, as the YAML file that sets it.
#include <iostream>

#include "apps/parkloc/command.h"
#include "apps/parkloc/config_args.h"

namespace {

const bool registered = parkloc::app::registerCommand([](CLI::App& parent) {
  auto args = std::make_shared<parkloc::app::ConfigArgs>();
  CLI::App* group = parkloc::app::commandGroup(parent, "config", "The configuration file");
  CLI::App* dump = group->add_subcommand(
      "dump", "Print every option with its value and reason (the defaults, or --config's)");
  args->addTo(dump);
  dump->callback([args] { std::cout << parkloc::config::dumpConfig(args->load()); });
});

}  // namespace
