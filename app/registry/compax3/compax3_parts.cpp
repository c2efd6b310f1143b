// Every part of the Parker Compax3 family, named in this one place. The
// GUI's and the CLI's part are compiled in only where the program links
// them (CAMBENCH_PARTS_GUI, CAMBENCH_PARTS_CLI: app/registry/sources.cmake).
#include "compax3_parts.h"

#include "app/cli/compax3/compax3_commands.h"
#include "comm/compax3/compax3_family.h"
#include "comm/compax3/compax3_protocol.h"
#include "comm/compax3/usecases/compax3_backup_part.h"
#include "comm/compax3/usecases/compax3_check.h"
#include "comm/sim/compax3/compax3_simulator.h"

#ifdef CAMBENCH_PARTS_GUI
#include "ui/compax3/compax3_gui.h"

// The GUI's part: the pages (the drive's address is a field its protocol
// declares, shown by the connection page).
static void registerCompax3Gui() {
    cambench::addFamilyGui<cambench::Compax3Gui>(QStringLiteral("compax3"));
}
#endif

cambench::FamilyParts cambench::compax3Parts() {
    return FamilyParts(QStringLiteral("compax3"), comm::registerCompax3Family,
                       comm::registerCompax3Protocol, comm::registerCompax3Simulator,
                       usecases::registerCompax3Check, usecases::registerCompax3Backup,
                       CAMBENCH_GUI_PART(registerCompax3Gui),
                       CAMBENCH_CLI_PART(cli::registerCompax3Commands));
}
