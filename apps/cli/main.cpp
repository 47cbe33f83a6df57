// smoothsteer: run scenarios, sweep parameters, tune from actuator limits, compare controllers.

#include <cstdio>
#include <exception>

#include "commands.hpp"
#include "smoothsteer/evaluation/controller_registration.hpp"

int main(int argc, char** argv) {
  CLI::App app{"smoothsteer: n-smooth, differentially bounded path-tracking control"};
  app.require_subcommand(1);
  // Scenario files may name every comparison controller (docs/baselines.md).
  smoothsteer::register_comparison_controllers();
  smoothsteer::cli::add_run_commands(app);
  smoothsteer::cli::add_tune_command(app);
  smoothsteer::cli::add_compare_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "smoothsteer: %s\n", error.what());
    return 1;
  }
  return 0;
}
