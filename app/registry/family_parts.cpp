#include "family_parts.h"

#include "comm/device/family_registry.h"
#include "comm/device/protocol_options.h"
#include "comm/device/protocol_registry.h"
#include "comm/sim/simulator_registry.h"
#include "comm/usecases/device_check.h"
#include "comm/usecases/family_backup.h"
#include "model/machine/machine_file.h"

#include <cstdio>

namespace cambench {

namespace {

QList<FamilyParts>& registered() {
    static QList<FamilyParts> families;
    return families;
}

const FamilyParts* findParts(const QString& id) {
    for (const FamilyParts& parts : registered())
        if (parts.id == id) return &parts;
    return nullptr;
}

// "family "xy" (Its Title)" as the sentences name it.
QString named(const comm::FamilyInfo& family) {
    return QStringLiteral("family \"%1\" (%2)").arg(family.id, family.title);
}

// What one built family lacks in `program`.
QStringList missingOf(const comm::FamilyInfo& family, Program program) {
    const FamilyParts* parts = findParts(family.id);
    if (!parts)
        return {QStringLiteral("%1 is registered, but not through its FamilyParts: name all its "
                               "parts in one place and register that (registerFamily)")
                    .arg(named(family))};
    QStringList missing;
    bool hasProtocol = false;
    for (const comm::ProtocolInfo* protocol : comm::ProtocolRegistry::instance().all())
        hasProtocol = hasProtocol || protocol->familyId == family.id;
    if (!hasProtocol) {
        missing << QStringLiteral("%1 has no protocol (FamilyParts::protocols)").arg(named(family));
    } else if (!comm::ProtocolRegistry::instance().find(family.defaultProtocol)) {
        missing << QStringLiteral("%1 names the default protocol \"%2\", which is not registered")
                       .arg(named(family), family.defaultProtocol);
    }
    if (!comm::SimulatorRegistry::instance().find(family.id))
        missing
            << QStringLiteral("%1 has no simulator (FamilyParts::simulator)").arg(named(family));
    if (program == Program::Simulator) return missing;
    if (!usecases::CheckRegistry::instance().find(family.id))
        missing << QStringLiteral("%1 has no checks (FamilyParts::checks)").arg(named(family));
    if (program == Program::Gui && !parts->gui)
        missing << QStringLiteral("%1 has no GUI part in the GUI program (FamilyParts::gui)")
                       .arg(named(family));
    if (program == Program::Cli && !parts->cli)
        missing << QStringLiteral("%1 has no command group in cambench-cli (FamilyParts::cli)")
                       .arg(named(family));
    return missing;
}

}  // namespace

void registerFamily(const FamilyParts& parts) {
    if (findParts(parts.id)) return;
    registered().append(parts);
    if (parts.family) {
        comm::FamilyInfo family = parts.family();
        family.id = parts.id;
        comm::FamilyRegistry::instance().add(family);
    }
    if (parts.protocols) {
        for (comm::ProtocolInfo protocol : parts.protocols()) {
            protocol.familyId = parts.id;
            comm::ProtocolRegistry::instance().add(protocol);
        }
    }
    // A machine file names its devices' protocol options as the command
    // line does; model/ learns them here.
    addMachineDeviceKeys(comm::protocolOptionNames());
    if (parts.simulator) {
        comm::SimulatorInfo simulator = parts.simulator();
        simulator.familyId = parts.id;
        comm::SimulatorRegistry::instance().add(simulator);
    }
    if (parts.checks) {
        usecases::FamilyCheck check = parts.checks();
        check.familyId = parts.id;
        usecases::CheckRegistry::instance().add(check);
    }
    if (parts.backup) usecases::BackupRegistry::instance().add(parts.id, parts.backup());
    if (parts.gui) parts.gui(parts.id);
    if (parts.cli) parts.cli(parts.id);
}

QList<FamilyParts> registeredFamilies() {
    return registered();
}

QStringList missingFamilyParts(Program program) {
    QStringList missing;
    for (const FamilyParts& parts : registered())
        if (!comm::FamilyRegistry::instance().find(parts.id))
            missing << QStringLiteral(
                           "the FamilyParts \"%1\" registers no family of that id "
                           "(FamilyParts::family)")
                           .arg(parts.id);
    for (const comm::FamilyInfo* family : comm::FamilyRegistry::instance().all())
        if (family->built) missing << missingOf(*family, program);
    return missing;
}

bool familiesComplete(Program program, const char* programName) {
    const QStringList missing = missingFamilyParts(program);
    for (const QString& line : missing)
        std::fprintf(stderr, "%s: this build is incomplete: %s.\n", programName, qPrintable(line));
    return missing.isEmpty();
}

}  // namespace cambench
