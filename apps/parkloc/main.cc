#include <iostream>
#include <vector>

#include "apps/parkloc/command.h"

namespace parkloc::app {
namespace {
std::vector<CommandSetup>& registry() {
  static std::vector<CommandSetup> commands;
  return commands;
}
}  // namespace

bool registerCommand(CommandSetup setup) {
  registry().push_back(std::move(setup));
  return true;
}
}  // namespace parkloc::app

int main(int argc, char** argv) {
  CLI::App app{"parkloc: vehicle positioning in parking garages from painted parking numbers"};
  app.require_subcommand(1);
  for (const auto& setup : parkloc::app::registry()) setup(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // Usage errors: one line, exit 2 (as getopt-style tools do); --help explains more.
    std::cerr << "parkloc: usage error: " << e.what() << " (see parkloc --help)\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "parkloc: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
