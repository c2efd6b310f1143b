// Every part of the MICRO DESIGN MC-1 family, named in this one place. The
// GUI's and the CLI's part are compiled in only where the program links
// them (CAMBENCH_PARTS_GUI, CAMBENCH_PARTS_CLI: app/registry/sources.cmake).
#include "mc1_parts.h"

#include "app/cli/mc1/mc1_commands.h"
#include "comm/mc1/mc1_family.h"
#include "comm/mc1/mc1_protocol.h"
#include "comm/mc1/usecases/mc1_backup_part.h"
#include "comm/mc1/usecases/mc1_check.h"
#include "comm/sim/mc1/mc1_simulator.h"
#include "model/mc1/mc1_family_id.h"

#ifdef CAMBENCH_PARTS_GUI
#include "ui/mc1/mc1_gui.h"
#include "ui/mc1/protocols/mc1_settings_widget.h"

// The GUI's part: the variant choice of the protocol, the pages.
static void registerMc1Gui(const QString& familyId) {
    cambench::ProtocolWidgetRegistry::instance().add(
        QStringLiteral("mc1"), [](const QString&) { return new cambench::Mc1SettingsWidget; });
    cambench::addFamilyGui<cambench::Mc1Gui>(familyId);
}
#endif

cambench::FamilyParts cambench::mc1Parts() {
    return FamilyParts(mc1FamilyId, comm::mc1Family, comm::mc1Protocols, comm::mc1Simulator,
                       usecases::mc1Check, usecases::mc1Backup, CAMBENCH_GUI_PART(registerMc1Gui),
                       CAMBENCH_CLI_PART(cli::registerMc1Commands));
}
