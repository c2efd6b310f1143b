// Which families' commands cambench-cli has: one line per family.
#include "commands.h"

#include "app/cli/camcon/camcon_commands.h"
#include "app/cli/compax3/compax3_commands.h"
#include "app/cli/mc1/mc1_commands.h"

namespace cambench::cli {

void registerCliCommands() {
    CommandRegistry& registry = CommandRegistry::instance();
    registerShellCommands(registry);
    registerCamConCommands(registry);
    registerMc1Commands(registry);
    registerCompax3Commands(registry);
}

}  // namespace cambench::cli
