// Placeholder until this subcommand group lands; replaced by its owner.
#include "commands.hpp"

namespace smoothsteer::cli {

void add_compare_command(CLI::App& app) { (void)app; }

}  // namespace smoothsteer::cli
