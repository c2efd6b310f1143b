#pragma once

#include "cli_options.h"
#include "cli_session.h"

#include <QList>
#include <QString>

#include <utility>

namespace cambench::cli {

// One command group. `run` parses its own arguments (usage errors before
// any device work), does its work through the session and returns the
// exit code.
struct CommandGroup {
    QString familyId;  // the family whose device it works on; empty: any family
    QString name;
    int (*run)(CliSession& session, CommandArgs& args) = nullptr;
    // The protocol it speaks when neither --protocol nor the port names one
    // (a command for a bus: backup-line); empty: the family's default.
    QString defaultProtocol = {};
};

// An option of a family's commands that says something of the device
// (--axes, --dictionary): taken before or after COMMAND, handed to the
// command's arguments, and naming its family as the command does.
struct FamilyOption {
    QString familyId;
    QString name;  // "--axes"; it takes a value
};

// The command groups of cambench-cli: the shell's own (ports, detect) and
// each family's, registered by its FamilyParts (app/registry/<family>/),
// with the family's part of --help. Nothing else lists them.
class CommandRegistry {
public:
    static CommandRegistry& instance();

    void add(CommandGroup group);
    // The family's lines of --help (its commands and what they print).
    void addHelp(const QString& familyId, const QString& text);

    // The group `name` for a device of `familyId` (its own, or one of any
    // family); null when there is none.
    const CommandGroup* find(const QString& familyId, const QString& name) const;
    // The families that have a group `name` ("mc1" for `mc1 ...`).
    QStringList familiesWith(const QString& name) const;
    // Whether any family (or the shell) has a group `name`.
    bool isCommand(const QString& name) const;
    QString help() const;
    // The lines of --help about `name` (a command group): its family's
    // whole part when the family has this one group, else its own lines;
    // empty for an unknown name.
    QString helpFor(const QString& name) const;

    void addOption(FamilyOption option);
    // Null when no family declared `name`.
    const FamilyOption* option(const QString& name) const;

private:
    QList<CommandGroup> m_groups;
    QList<FamilyOption> m_options;
    QList<std::pair<QString, QString>> m_help;
};

// The shell's own groups: ports, detect, check, machine, help.
void registerShellCommands(CommandRegistry& registry);

// "read" or "write" after a group name; a usage error for anything else.
Result<QString> takeVerb(CommandArgs& args, const QStringList& verbs);

// One family's part of the CommandRegistry, as its FamilyParts' CLI part
// gets it (CAMBENCH_CLI_PART): every group, option and help text it adds
// is that family's, so the part never spells its family's id.
class FamilyCommands {
public:
    FamilyCommands(CommandRegistry& registry, QString familyId)
        : m_registry(registry), m_familyId(std::move(familyId)) {}

    // The group `name`; `defaultProtocol` as CommandGroup's.
    void add(const QString& name, int (*run)(CliSession& session, CommandArgs& args),
             const QString& defaultProtocol = {}) {
        m_registry.add({m_familyId, name, run, defaultProtocol});
    }
    // An option of its commands (FamilyOption).
    void addOption(const QString& name) { m_registry.addOption({m_familyId, name}); }
    // Its lines of --help.
    void addHelp(const QString& text) { m_registry.addHelp(m_familyId, text); }

private:
    CommandRegistry& m_registry;
    QString m_familyId;
};

}  // namespace cambench::cli
