#pragma once
// Each subcommand lives in its own cmd_*.cc and registers itself here; main.cc parses and
// turns any exception into one line on stderr and a non-zero exit.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>

namespace parkloc::app {

using CommandSetup = std::function<void(CLI::App& parent)>;

// Called from a static initializer in each cmd_*.cc; returns true.
bool registerCommand(CommandSetup setup);

// The command group `name` (e.g. "train") under `parent`, created by whichever file asks
// first: the order of static initializers across files is unspecified.
inline CLI::App* commandGroup(CLI::App& parent, const std::string& name,
                              const std::string& description) {
  for (CLI::App* sub : parent.get_subcommands([](CLI::App*) { return true; }))
    if (sub->get_name() == name) return sub;
  CLI::App* group = parent.add_subcommand(name, description);
  group->require_subcommand(1);
  return group;
}

}  // namespace parkloc::app
