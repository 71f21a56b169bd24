#include <iostream>

#include "apps/parkloc/command.h"

namespace {
const bool registered = parkloc::app::registerCommand([](CLI::App& parent) {
  auto* cmd = parent.add_subcommand("version", "Print the parkloc version");
  cmd->callback([] { std::cout << "parkloc " << PARKLOC_VERSION << "\n"; });
});
}  // namespace
