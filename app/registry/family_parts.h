#pragma once

#include <QList>
#include <QString>
#include <QStringList>

#include <memory>
#include <utility>

#ifdef CAMBENCH_PARTS_GUI
#include "ui/family_gui.h"
#endif

namespace cambench {

namespace comm {
struct FamilyInfo;
struct ProtocolInfo;
struct SimulatorInfo;
}  // namespace comm
namespace usecases {
class FamilyBackup;
struct FamilyCheck;
}  // namespace usecases

// Every part of one device family, named in one place: for a built-in
// family its app/registry/<family>/<family>_parts.cpp, listed once in
// app/registry/builtin_registry.cpp; the tests' fake family names its own
// (tests/family/). Each part is a function that makes it; registerFamily
// puts what it makes in the registry the shell reads it from, keyed by
// `id`: a part never spells its family's id, so no part can land under
// another family's. The GUI's and the CLI's part are null in a program
// that does not link them (the GUI in cambench-cli).
struct FamilyParts {
    // A part of the GUI or of the CLI: registers itself as `familyId`'s.
    using Register = void (*)(const QString& familyId);
    FamilyParts() = default;
    // Every part in the order of the members below.
    FamilyParts(QString id, comm::FamilyInfo (*family)(), QList<comm::ProtocolInfo> (*protocols)(),
                comm::SimulatorInfo (*simulator)(), usecases::FamilyCheck (*checks)(),
                std::shared_ptr<const usecases::FamilyBackup> (*backup)(), Register gui,
                Register cli)
        : id(std::move(id)),
          family(family),
          protocols(protocols),
          simulator(simulator),
          checks(checks),
          backup(backup),
          gui(gui),
          cli(cli) {}

    // Its id (the family's *_family_id.h constant): the --family value,
    // FamilyInfo::id, and the key of every part below in its registry.
    QString id;
    // Its FamilyInfo (title, default protocol; its id is `id`).
    comm::FamilyInfo (*family)() = nullptr;
    // Every protocol of the family (their familyId is `id`).
    QList<comm::ProtocolInfo> (*protocols)() = nullptr;
    // Its simulated device (the in-process `sim` port, cambench-sim --family).
    comm::SimulatorInfo (*simulator)() = nullptr;
    // Its checks and their gate (cambench-cli check, Help -> Check this device).
    usecases::FamilyCheck (*checks)() = nullptr;
    // Its backup, verify, diff and restore of one device, typed
    // (usecases::FamilyBackup, comm/usecases/family_backup.h): the
    // single-device commands, the machine commands and the machine window
    // call it. A family without one: a machine backup says "the xy family
    // has no backup" for its devices.
    std::shared_ptr<const usecases::FamilyBackup> (*backup)() = nullptr;
    // The GUI's part: its protocols' settings widgets (ProtocolWidgetRegistry)
    // and its FamilyGui (FamilyGuiRegistry).
    Register gui = nullptr;
    // The CLI's part: its command groups and their part of --help
    // (cli::CommandRegistry, through cli::FamilyCommands).
    Register cli = nullptr;
};

// A part of the GUI or the CLI in a family's parts file: the function
// where the program links that part (its registration is compiled with
// CAMBENCH_PARTS_GUI or CAMBENCH_PARTS_CLI, app/registry/sources.cmake),
// else null.
#ifdef CAMBENCH_PARTS_GUI
#define CAMBENCH_GUI_PART(function) function
// Registers Gui, a FamilyGui, as family `familyId`'s (a GUI part's last
// line).
template <class Gui>
void addFamilyGui(const QString& familyId) {
    FamilyGuiRegistry::instance().add({familyId, [](DeviceSession* session, QObject* parent) {
                                           return new Gui(session, parent);
                                       }});
}
#else
#define CAMBENCH_GUI_PART(function) nullptr
#endif
#ifdef CAMBENCH_PARTS_CLI
#define CAMBENCH_CLI_PART(function)                                               \
    [](const QString& familyId) {                                                 \
        cli::FamilyCommands commands(cli::CommandRegistry::instance(), familyId); \
        function(commands);                                                       \
    }
#else
#define CAMBENCH_CLI_PART(function) nullptr
#endif

// The programs, for what each must have of every family it hosts.
enum class Program {
    Simulator,  // cambench-sim: family, protocols, simulator
    Cli,        // cambench-cli: those, its checks and its command groups
    Gui,        // cambench: those, its checks and its GUI part
};

// Registers each part `parts` has (a null one is left out). A family
// registered before (by id) is left as it is: safe to call more than once.
void registerFamily(const FamilyParts& parts);
// The families registered through registerFamily, in that order.
QList<FamilyParts> registeredFamilies();

// The startup check: every family the FamilyRegistry holds as built must
// have been registered through its FamilyParts, with a protocol (its
// default one among them) and a simulator registered, and with the checks
// and the GUI or CLI part `program` needs. One sentence per missing part,
// naming the family and the part; empty when every family is complete.
QStringList missingFamilyParts(Program program);

// For main(): prints each missing part to stderr after `programName` and
// returns false when there is one (the program then stops).
bool familiesComplete(Program program, const char* programName);

}  // namespace cambench
