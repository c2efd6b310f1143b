#include "commands.h"

#include "comm/device/family_registry.h"

#include <algorithm>

namespace cambench::cli {

int runPorts(CliSession& session, CommandArgs& args);    // port_commands.cpp
int runDetect(CliSession& session, CommandArgs& args);   // detect_command.cpp
int runCheck(CliSession& session, CommandArgs& args);    // check_command.cpp
int runMachine(CliSession& session, CommandArgs& args);  // machine_command.cpp
int runHelp(CliSession& session, CommandArgs& args);     // help_command.cpp

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

bool CommandRegistry::isCommand(const QString& name) const {
    for (const CommandGroup& group : m_groups)
        if (group.name == name) return true;
    return false;
}

void CommandRegistry::addOption(FamilyOption option) {
    m_options.append(std::move(option));
}

const FamilyOption* CommandRegistry::option(const QString& name) const {
    for (const FamilyOption& option : m_options)
        if (option.name == name) return &option;
    return nullptr;
}

namespace {

QString familyHeading(const QString& familyId) {
    const comm::FamilyInfo* family = comm::FamilyRegistry::instance().find(familyId);
    return QStringLiteral("%1 (--family %2):\n").arg(family ? family->title : familyId, familyId);
}

// The lines of `text` about command `name`: each line "  name ..." and the
// more deeply indented lines that go on from it.
QString entryLines(const QString& text, const QString& name) {
    QString lines;
    bool inEntry = false;
    const QString start = QStringLiteral("  ") + name;
    for (const QString& line : text.split(QLatin1Char('\n'))) {
        const bool starts = line.startsWith(start) &&
                            (line.size() == start.size() || line.at(start.size()) == u' ');
        if (starts || (inEntry && line.startsWith(QLatin1String("   ")))) {
            lines += line + QLatin1Char('\n');
            inEntry = true;
        } else {
            inEntry = false;
        }
    }
    return lines;
}

}  // namespace

QString CommandRegistry::help() const {
    QString text;
    for (const auto& [familyId, lines] : m_help)
        text += QLatin1Char('\n') + familyHeading(familyId) + lines;
    return text;
}

QString CommandRegistry::helpFor(const QString& name) const {
    const auto group = std::find_if(m_groups.cbegin(), m_groups.cend(),
                                    [&name](const CommandGroup& g) { return g.name == name; });
    if (group == m_groups.cend()) return {};
    const QString familyId = group->familyId;
    const bool familysOnly =
        !familyId.isEmpty() &&
        std::count_if(m_groups.cbegin(), m_groups.cend(),
                      [&familyId](const CommandGroup& g) { return g.familyId == familyId; }) == 1;
    if (familysOnly) {
        QString text;
        for (const auto& [id, lines] : m_help)
            if (id == familyId) text += familyHeading(id) + lines;
        if (!text.isEmpty()) return text;
    }
    return entryLines(usageText(), name);
}

void registerShellCommands(CommandRegistry& registry) {
    registry.add({{}, QStringLiteral("ports"), runPorts});
    registry.add({{}, QStringLiteral("detect"), runDetect});
    registry.add({{}, QStringLiteral("check"), runCheck});
    registry.add({{}, QStringLiteral("machine"), runMachine});
    registry.add({{}, QStringLiteral("help"), runHelp});
}

Result<QString> takeVerb(CommandArgs& args, const QStringList& verbs) {
    const QString verb = args.takePositional();
    if (verbs.contains(verb)) return verb;
    return Error::usage(
        QStringLiteral("%1 needs one of: %2%3")
            .arg(args.command(), verbs.join(QLatin1String(", ")),
                 verb.isEmpty() ? QString() : QStringLiteral(" (not \"%1\")").arg(verb)));
}

}  // namespace cambench::cli
