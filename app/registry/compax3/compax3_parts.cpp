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
#include "model/compax3/compax3_family_id.h"

#ifdef CAMBENCH_PARTS_GUI
#include "ui/compax3/compax3_gui.h"

// The GUI's part: the pages (the drive's address is a field its protocol
// declares, shown by the connection page).
static void registerCompax3Gui(const QString& familyId) {
    cambench::addFamilyGui<cambench::Compax3Gui>(familyId);
}
#endif

cambench::FamilyParts cambench::compax3Parts() {
    return FamilyParts(compax3FamilyId, comm::compax3Family, comm::compax3Protocols,
                       comm::compax3Simulator, usecases::compax3Check, usecases::compax3Backup,
                       CAMBENCH_GUI_PART(registerCompax3Gui),
                       CAMBENCH_CLI_PART(cli::registerCompax3Commands));
}
