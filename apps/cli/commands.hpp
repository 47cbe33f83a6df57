#pragma once
//! Subcommand registration of the `smoothsteer` CLI. Each group lives in its own file:
//!   run_commands.cpp     - run, list, sweep    (simulation, issue "Simulation")
//!   tune_command.cpp     - tune                (parametrization)
//!   compare_command.cpp  - compare             (comparison benchmarks)
//! A registration function adds its subcommand(s) and their callbacks to the app. Callbacks
//! report errors by throwing std::exception; main() prints "smoothsteer: <message>" and exits 1.

#include <CLI/CLI.hpp>

namespace smoothsteer::cli {

void add_run_commands(CLI::App& app);
void add_tune_command(CLI::App& app);
void add_compare_command(CLI::App& app);

}  // namespace smoothsteer::cli
