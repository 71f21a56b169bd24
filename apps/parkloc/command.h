#pragma once
// Each subcommand lives in its own cmd_*.cc and registers itself here; main.cc parses and
// turns any exception into one line on stderr and a non-zero exit.
#include <CLI/CLI.hpp>
#include <functional>

namespace parkloc::app {

using CommandSetup = std::function<void(CLI::App& parent)>;

// Called from a static initializer in each cmd_*.cc; returns true.
bool registerCommand(CommandSetup setup);

}  // namespace parkloc::app
