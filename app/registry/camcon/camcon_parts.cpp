// Every part of the Digitronic CamCon family, named in this one place. The
// GUI's and the CLI's part are compiled in only where the program links
// them (CAMBENCH_PARTS_GUI, CAMBENCH_PARTS_CLI: app/registry/sources.cmake).
#include "camcon_parts.h"

#include "app/cli/camcon/camcon_commands.h"
#include "comm/camcon/ascii/ascii_protocol.h"
#include "comm/camcon/cambus/cambus_protocol.h"
#include "comm/camcon/camcon_family.h"
#include "comm/camcon/table/table_protocol.h"
#include "comm/camcon/usecases/camcon_backup_part.h"
#include "comm/camcon/usecases/camcon_check.h"
#include "comm/device/protocol_registry.h"
#include "comm/sim/camcon/camcon_simulator.h"
#include "model/camcon/camcon_family_id.h"

#ifdef CAMBENCH_PARTS_GUI
#include "ui/camcon/cambus/cambus_settings_widget.h"
#include "ui/camcon/camcon_gui.h"
#include "ui/camcon/protocols/table_settings_widget.h"

// The GUI's part: the settings widgets of the protocols that show more
// than their options' fields (Cam-BUS: the bus; the table interface: the
// choice of its variant), the CamCon's workspace and pages.
static void registerCamConGui(const QString& familyId) {
    using namespace cambench;
    ProtocolWidgetRegistry& widgets = ProtocolWidgetRegistry::instance();
    widgets.add(QStringLiteral("cambus"), [](const QString&) { return new CamBusSettingsWidget; });
    for (const char* id : {"3964r-n96", "3964r-e38"}) {
        widgets.add(QLatin1String(id),
                    [](const QString& protocol) { return new TableSettingsWidget(protocol); });
    }
    addFamilyGui<CamConGui>(familyId);
}
#endif

// Its protocols: ASCII (Standard, Multiuser), the table interface (two
// 3964R variants), the Cam-BUS.
static QList<cambench::comm::ProtocolInfo> camconProtocols() {
    using namespace cambench::comm;
    return camconAsciiProtocols() + camconTableProtocols() + QList{camconCamBusProtocol()};
}

cambench::FamilyParts cambench::camconParts() {
    return FamilyParts(camconFamilyId, comm::camconFamily, camconProtocols, comm::camconSimulator,
                       usecases::camconCheck, usecases::camconBackup,
                       CAMBENCH_GUI_PART(registerCamConGui),
                       CAMBENCH_CLI_PART(cli::registerCamConCommands));
}
