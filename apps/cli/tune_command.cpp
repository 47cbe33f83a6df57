// Placeholder until this subcommand group lands; replaced by its owner.
#include "commands.hpp"

namespace smoothsteer::cli {

void add_tune_command(CLI::App& app) { (void)app; }

}  // namespace smoothsteer::cli
