#include "commands.h"

#include "comm/device/family_registry.h"

namespace cambench::cli {

int runPorts(CliSession& session, CommandArgs& args);    // port_commands.cpp
int runDetect(CliSession& session, CommandArgs& args);   // detect_command.cpp
int runCheck(CliSession& session, CommandArgs& args);    // check_command.cpp
int runMachine(CliSession& session, CommandArgs& args);  // machine_command.cpp

CommandRegistry& CommandRegistry::instance() {
    static CommandRegistry registry;
    return registry;
}

void CommandRegistry::add(CommandGroup group) {
    m_groups.append(std::move(group));
}

void CommandRegistry::addHelp(const QString& familyId, const QString& text) {
    m_help.append({familyId, text});
}

const CommandGroup* CommandRegistry::find(const QString& familyId, const QString& name) const {
    for (const CommandGroup& group : m_groups) {
        if (group.name == name && (group.familyId.isEmpty() || group.familyId == familyId))
            return &group;
    }
    return nullptr;
}

QStringList CommandRegistry::familiesWith(const QString& name) const {
    QStringList families;
    for (const CommandGroup& group : m_groups) {
        if (group.name == name && !group.familyId.isEmpty()) families << group.familyId;
    }
    return families;
}

QString CommandRegistry::help() const {
    QString text;
    for (const auto& [familyId, lines] : m_help) {
        const comm::FamilyInfo* family = comm::FamilyRegistry::instance().find(familyId);
        text += QStringLiteral("\n%1 (--family %2):\n")
                    .arg(family ? family->title : familyId, familyId) +
                lines;
    }
    return text;
}

void registerShellCommands(CommandRegistry& registry) {
    registry.add({{}, QStringLiteral("ports"), runPorts});
    registry.add({{}, QStringLiteral("detect"), runDetect});
    registry.add({{}, QStringLiteral("check"), runCheck});
    registry.add({{}, QStringLiteral("machine"), runMachine});
}

Result<QString> takeVerb(CommandArgs& args, const QStringList& verbs) {
    const QString verb = args.takePositional();
    if (verbs.contains(verb)) return verb;
    return Error::usage(
        QStringLiteral("%1 needs one of: %2%3; see `cambench-cli --help`")
            .arg(args.command(), verbs.join(QLatin1String(", ")),
                 verb.isEmpty() ? QString() : QStringLiteral(" (not \"%1\")").arg(verb)));
}

}  // namespace cambench::cli
