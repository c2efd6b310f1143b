#pragma once

#include "cli_options.h"
#include "cli_session.h"

#include <QList>
#include <QString>

namespace cambench::cli {

// One command group. `run` parses its own arguments (usage errors before
// any device work), does its work through the session and returns the
// exit code.
struct CommandGroup {
    QString familyId;  // the family whose device it works on; empty: any family
    QString name;
    int (*run)(CliSession& session, CommandArgs& args) = nullptr;
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
    QString help() const;

private:
    QList<CommandGroup> m_groups;
    QList<std::pair<QString, QString>> m_help;
};

// The shell's own groups: ports, detect.
void registerShellCommands(CommandRegistry& registry);

// "read" or "write" after a group name; a usage error for anything else.
Result<QString> takeVerb(CommandArgs& args, const QStringList& verbs);

}  // namespace cambench::cli
