// smoothsteer: run scenarios, sweep parameters, tune from actuator limits, compare controllers.
// Exit status (docs/cli.md): 0 success, 1 any error (bad command line, bad input, failed run),
// 130 interrupted (SIGINT or SIGTERM during a long command; it has said what was finished).

#include <cstdio>
#include <exception>
#include <new>
#include <string>

#include "commands.hpp"
#include "smoothsteer/evaluation/controller_registration.hpp"
#include "smoothsteer/runner/progress.hpp"
#include "smoothsteer/runner/run_output.hpp"

int main(int argc, char** argv) {
  CLI::App app{"smoothsteer: n-smooth, differentially bounded path-tracking control"};
  app.set_version_flag("--version", "smoothsteer " + smoothsteer::runner::tool_version() +
                                        " (commit " + smoothsteer::runner::tool_commit() + ")");
  app.require_subcommand(1);
  // Scenario files may name every comparison controller (docs/baselines.md).
  smoothsteer::register_comparison_controllers();
  smoothsteer::cli::add_run_commands(app);
  smoothsteer::cli::add_tune_command(app);
  smoothsteer::cli::add_compare_command(app);
  const std::string command = argc > 1 ? std::string(" ") + argv[1] : std::string();
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& success) {  // --help, --version
    return app.exit(success);
  } catch (const CLI::ParseError& error) {
    app.exit(error);  // prints the message and the usage hint; CLI11's own codes are not ours
    return 1;
  } catch (const smoothsteer::runner::Interrupted&) {
    return 130;  // 128 + SIGINT, as a shell reports a process that Ctrl-C ended
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr,
                 "smoothsteer%s: out of memory (std::bad_alloc); an input asks for more than "
                 "this machine has\n",
                 command.c_str());
    return 1;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "smoothsteer%s: %s\n", command.c_str(), error.what());
    return 1;
  }
  return 0;
}
