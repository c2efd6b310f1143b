#include "cli_options.h"

#include "commands.h"

#include "comm/device/family_registry.h"
#include "comm/transport/transport_registry.h"

namespace cambench::cli {

namespace {

Error usageError(const QString& what) {
    return Error::usage(what);
}

// Splits `--name=value`; returns true when `arg` names option `name`.
bool matchesOption(const QString& arg, const QString& name, QString* inlineValue) {
    if (arg == name) return true;
    if (name.startsWith(QLatin1String("--")) && arg.startsWith(name + QLatin1Char('='))) {
        *inlineValue = arg.mid(name.size() + 1);
        return true;
    }
    return false;
}

}  // namespace

const comm::ProtocolInfo& GlobalOptions::protocolInfo() const {
    const comm::ProtocolInfo* info = comm::ProtocolRegistry::instance().find(protocol);
    Q_ASSERT(info);
    return *info;
}

int GlobalOptions::effectiveBaud() const {
    if (baud > 0) return baud;
    return protocolInfo().defaultSerial.baud;
}

comm::ConnectionSettings GlobalOptions::connection() const {
    comm::ConnectionSettings connection;
    connection.port = port;
    connection.serial = protocolInfo().defaultSerial;
    connection.serial.baud = effectiveBaud();
    connection.protocol = protocolInfo().id;
    return connection;
}

comm::ProtocolSettingsPtr GlobalOptions::protocolSettings() const {
    return comm::ProtocolSettingsPtr(comm::settingsWith(protocolInfo(), protocolValues, timeoutMs));
}

Result<int> parseIntArgument(const QString& text, const QString& what, int min, int max) {
    bool ok = false;
    const int value = text.toInt(&ok, 10);
    if (!ok || value < min || value > max) {
        return usageError(QStringLiteral("%1 must be a whole number from %2 to %3, not \"%4\"")
                              .arg(what)
                              .arg(min)
                              .arg(max)
                              .arg(text));
    }
    return value;
}

namespace {

// The options of the shell, each taking a value.
const QStringList& shellOptions() {
    static const QStringList names = {QStringLiteral("--port"),     QStringLiteral("--family"),
                                      QStringLiteral("--protocol"), QStringLiteral("--baud"),
                                      QStringLiteral("--timeout"),  QStringLiteral("--log")};
    return names;
}

// The protocol option `arg` names ("device" of "--device"), or empty.
QString protocolOptionOf(const QString& optionWord) {
    if (!optionWord.startsWith(QLatin1String("--"))) return {};
    const QString name = optionWord.mid(2);
    return comm::protocolOptionNames().contains(name) ? name : QString();
}

// An option word, not a value: "-5" is a number and "-" stdin or stdout.
bool isOptionWord(const QString& arg) {
    return arg.size() > 1 && arg.startsWith(QLatin1Char('-')) && !arg.at(1).isDigit();
}

// The name of option word `arg` ("--port" of "--port=x"), and its inline value.
QString optionName(const QString& arg, QString* inlineValue, bool* hasInline) {
    const qsizetype eq = arg.indexOf(QLatin1Char('='));
    *hasInline = arg.startsWith(QLatin1String("--")) && eq > 2;
    if (!*hasInline) return arg;
    *inlineValue = arg.mid(eq + 1);
    return arg.left(eq);
}

// Something on the command line that names a device family, in words for
// a message when another names a different one.
struct FamilyClaim {
    QString familyId;
    QString says;
};

// Each family a family-specific word of the command line names: its
// protocol, the protocol its port names, the command, a family's option,
// a protocol's option.
struct Given {
    QString family;
    QString protocol;
    QStringList familyOptions;  // "--axes", in order
};

QList<FamilyClaim> familyClaims(const GlobalOptions& options, const Given& given,
                                const QString& portProtocol) {
    QList<FamilyClaim> claims;
    const comm::ProtocolRegistry& protocols = comm::ProtocolRegistry::instance();
    if (!given.family.isEmpty())
        claims << FamilyClaim{
            given.family, QStringLiteral("--family %1 asks for the %1 family").arg(given.family)};
    if (!given.protocol.isEmpty())
        claims << FamilyClaim{protocols.find(given.protocol)->familyId,
                              QStringLiteral("--protocol %1 is a protocol of the %2 family")
                                  .arg(given.protocol, protocols.find(given.protocol)->familyId)};
    if (const comm::ProtocolInfo* named = protocols.find(portProtocol))
        claims << FamilyClaim{named->familyId,
                              QStringLiteral("the port %1 speaks %2, a protocol of the %3 family")
                                  .arg(options.port, named->id, named->familyId)};
    const QStringList commandFamilies = CommandRegistry::instance().familiesWith(options.command);
    if (commandFamilies.size() == 1)
        claims << FamilyClaim{commandFamilies.first(),
                              QStringLiteral("\"%1\" is a command of the %2 family")
                                  .arg(options.command, commandFamilies.first())};
    for (const QString& name : given.familyOptions) {
        const QString family = CommandRegistry::instance().option(name)->familyId;
        claims << FamilyClaim{family,
                              QStringLiteral("%1 is an option of the %2 family").arg(name, family)};
    }
    // An option only one family's protocols take (--address 7: a drive's
    // address; --variant mc200v2: a controller of the mc1 family).
    for (const auto& [name, value] : options.protocolValues) {
        const QStringList families = comm::familiesTaking(name, value);
        if (families.size() == 1)
            claims << FamilyClaim{families.first(),
                                  QStringLiteral("--%1 %2 is for a protocol of the %3 family")
                                      .arg(name, value, families.first())};
    }
    return claims;
}

// Sets the value of shell option `name`.
Status applyShellOption(GlobalOptions& options, Given& given, const QString& name,
                        const QString& value) {
    if (name == QLatin1String("--port")) {
        options.port = value;
    } else if (name == QLatin1String("--family")) {
        const Result<const comm::FamilyInfo*> family =
            comm::FamilyRegistry::instance().usable(value);
        if (!family) return usageError(family.error().message);
        given.family = (*family)->id;
    } else if (name == QLatin1String("--protocol")) {
        const comm::ProtocolInfo* info = comm::ProtocolRegistry::instance().find(value);
        if (!info) {
            return usageError(QStringLiteral("--protocol must be one of %1, not \"%2\"")
                                  .arg(comm::ProtocolRegistry::instance().idList(), value));
        }
        given.protocol = info->id;
    } else if (name == QLatin1String("--log")) {
        options.logFile = value;
    } else {
        struct Range {
            const char* name;
            int min;
            int max;
            int* target;
        };
        const Range ranges[] = {{"--baud", 50, 4000000, &options.baud},
                                {"--timeout", 10, 600000, &options.timeoutMs}};
        for (const Range& range : ranges) {
            if (name != QLatin1String(range.name)) continue;
            const Result<int> number = parseIntArgument(value, name, range.min, range.max);
            if (!number) return number.error();
            *range.target = *number;
            if (range.target == &options.timeoutMs) options.timeoutGiven = true;
        }
    }
    return success();
}

// The family and protocol every family-specific word of the line names;
// a usage error naming two that disagree.
Status resolveFamilyAndProtocol(GlobalOptions& options, const Given& given) {
    const QString portProtocol = comm::TransportRegistry::instance().namedProtocol(options.port);
    if (!portProtocol.isEmpty() && !given.protocol.isEmpty() && portProtocol != given.protocol)
        return usageError(QStringLiteral("the port %1 speaks %2, but --protocol %3 was given; "
                                         "drop one of them")
                              .arg(options.port, portProtocol, given.protocol));
    const QList<FamilyClaim> claims = familyClaims(options, given, portProtocol);
    for (const FamilyClaim& claim : claims) {
        if (claim.familyId != claims.first().familyId)
            return usageError(QStringLiteral("%1, but %2; drop one of them")
                                  .arg(claims.first().says, claim.says));
    }
    options.family =
        claims.isEmpty() ? comm::FamilyRegistry::instance().defaultId() : claims.first().familyId;
    const Result<const comm::FamilyInfo*> family =
        comm::FamilyRegistry::instance().usable(options.family);
    if (!family) return usageError(family.error().message);
    const CommandGroup* group = CommandRegistry::instance().find(options.family, options.command);
    if (!given.protocol.isEmpty()) {
        options.protocol = given.protocol;
    } else if (!portProtocol.isEmpty()) {
        options.protocol = portProtocol;
    } else {
        const QString preferred = group && !group->defaultProtocol.isEmpty()
                                      ? group->defaultProtocol
                                      : (*family)->defaultProtocol;
        const Result<const comm::ProtocolInfo*> taking = comm::protocolTaking(
            options.family, preferred, options.protocolValues, comm::commandLineOption);
        if (!taking) return taking.error();
        options.protocol = (*taking)->id;
    }
    return comm::checkOptionValues(options.protocolInfo(), options.protocolValues,
                                   comm::commandLineOption);
}

}  // namespace

Result<GlobalOptions> parseGlobalOptions(const QStringList& args) {
    GlobalOptions options;
    Given given;
    const CommandRegistry& commands = CommandRegistry::instance();
    QStringList before;  // a command's options before COMMAND: handed to it after its own words
    QStringList after;
    QStringList familyArgs;  // the families' options, wherever they stood
    bool haveCommand = false;
    for (int i = 0; i < args.size(); ++i) {
        const QString& arg = args.at(i);
        if (!isOptionWord(arg)) {
            if (haveCommand) {
                after << arg;
            } else {
                options.command = arg;
                haveCommand = true;
            }
            continue;
        }
        QString inlineValue;
        bool hasInline = false;
        const QString name = optionName(arg, &inlineValue, &hasInline);
        const bool shell = shellOptions().contains(name);
        const QString protocolOption = protocolOptionOf(name);
        if (shell || !protocolOption.isEmpty() || commands.option(name)) {
            if (!hasInline && i + 1 >= args.size())
                return usageError(QStringLiteral("%1 needs a value").arg(name));
            const QString value = hasInline ? inlineValue : args.at(++i);
            if (!protocolOption.isEmpty()) {
                options.protocolValues << qMakePair(protocolOption, value);
            } else if (shell) {
                if (const Status applied = applyShellOption(options, given, name, value); !applied)
                    return applied.error();
            } else {
                familyArgs << name << value;
                if (!given.familyOptions.contains(name)) given.familyOptions << name;
            }
            continue;
        }
        if (haveCommand) {
            after << arg;
            continue;
        }
        // A command's own option before COMMAND: the next word is its value
        // unless it is an option or a command (`--json info`); a value that
        // is a command's name is written --name=VALUE there.
        before << arg;
        if (!hasInline && i + 1 < args.size() && !isOptionWord(args.at(i + 1)) &&
            !commands.isCommand(args.at(i + 1)))
            before << args.at(++i);
    }
    if (options.command.isEmpty()) return usageError(QStringLiteral("no COMMAND given"));
    options.commandArgs = after + before + familyArgs;
    if (const Status resolved = resolveFamilyAndProtocol(options, given); !resolved)
        return resolved.error();
    return options;
}

bool CommandArgs::takeFlag(const QString& name) {
    return m_args.removeOne(name);
}

Result<QString> CommandArgs::takeOption(const QString& name, const QString& shortName) {
    for (int i = 0; i < m_args.size(); ++i) {
        QString inlineValue;
        const bool isLong = matchesOption(m_args.at(i), name, &inlineValue);
        if (!isLong && (shortName.isEmpty() || m_args.at(i) != shortName)) continue;
        if (isLong && m_args.at(i).contains(QLatin1Char('='))) {
            m_args.removeAt(i);
            return inlineValue;
        }
        if (i + 1 >= m_args.size()) {
            return usageError(QStringLiteral("%1 %2 needs a value").arg(m_command, m_args.at(i)));
        }
        const QString value = m_args.at(i + 1);
        m_args.remove(i, 2);
        return value;
    }
    return QString();
}

Result<int> CommandArgs::takeIntOption(const QString& name, int fallback, int min, int max) {
    const Result<QString> text = takeOption(name);
    if (!text) return text.error();
    if (text->isEmpty()) return fallback;
    return parseIntArgument(*text, name, min, max);
}

QString CommandArgs::takePositional() {
    for (int i = 0; i < m_args.size(); ++i) {
        const QString& arg = m_args.at(i);
        // A lone "-" is stdin/stdout and "-5" a negative number.
        const bool negative = arg.size() > 1 && arg.at(1).isDigit();
        if (arg.startsWith(QLatin1Char('-')) && arg != QLatin1String("-") && !negative) continue;
        return m_args.takeAt(i);
    }
    return {};
}

Result<QString> CommandArgs::takeRequiredPositional(const QString& what) {
    const QString value = takePositional();
    if (value.isEmpty()) return usageError(QStringLiteral("%1 needs %2").arg(m_command, what));
    return value;
}

Status CommandArgs::finish() const {
    if (m_args.isEmpty()) return success();
    return usageError(QStringLiteral("%1 does not take \"%2\"").arg(m_command, m_args.join(u' ')));
}

Result<QList<int>> parseDeviceNumbers(const QString& text, const QString& what) {
    QList<int> numbers;
    for (const QString& part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const Result<int> number = parseIntArgument(part.trimmed(), what, 0, 63);
        if (!number) return number.error();
        if (numbers.contains(*number))
            return usageError(QStringLiteral("%1 lists device %2 twice").arg(what).arg(*number));
        numbers.append(*number);
    }
    if (numbers.isEmpty())
        return usageError(QStringLiteral("%1 needs device numbers such as 0,5").arg(what));
    return numbers;
}

namespace {

// An option name as protocols declare it: the first declaration (its
// help, range and words) and every protocol that has it by that name (one
// that has it as an older name is listed with the name it has now).
struct Declared {
    const comm::ProtocolOption* first = nullptr;
    QStringList protocols;
};

Declared declarationsOf(const QString& name) {
    Declared declared;
    for (const comm::ProtocolInfo* protocol : comm::ProtocolRegistry::instance().all()) {
        const comm::ProtocolOption* option = comm::declaredOption(*protocol, name);
        if (!option || option->name != name) continue;
        if (!declared.first) declared.first = option;
        declared.protocols << protocol->id;
    }
    return declared;
}

// "--device N", "--variant V".
QString optionWord(const QString& name, const comm::ProtocolOption& option) {
    return QStringLiteral("--%1 %2").arg(name, option.isChoice() ? "V" : "N");
}

// The --help lines of the options protocols declare: each name once, with
// its help, its range or words, and the protocols that take it.
QString protocolOptionsHelp() {
    QString lines;
    for (const QString& name : comm::protocolOptionNames()) {
        const Declared declared = declarationsOf(name);
        const comm::ProtocolOption* first = declared.first;
        if (!first) continue;
        const QString values =
            first->isChoice()
                ? QStringLiteral("%1 (default %2)")
                      .arg(first->choices.join(QStringLiteral(", ")), first->choices.first())
                : QStringLiteral("%1..%2 (default %3)")
                      .arg(first->min)
                      .arg(first->max)
                      .arg(first->fallback);
        lines +=
            QStringLiteral("  %1%2\n                %3; %4%5\n")
                .arg(optionWord(name, *first).leftJustified(14), first->help, values,
                     declared.protocols.join(QStringLiteral(", ")),
                     first->aliases.isEmpty() ? QString()
                                              : QStringLiteral("; also --") +
                                                    first->aliases.join(QStringLiteral(", --")));
    }
    return lines;
}

// "[--device N] [--pc-number N] ..." for the usage line.
QString protocolOptionsUsage() {
    QStringList words;
    for (const QString& name : comm::protocolOptionNames())
        if (const comm::ProtocolOption* first = declarationsOf(name).first)
            words << QLatin1Char('[') + optionWord(name, *first) + QLatin1Char(']');
    return words.join(u' ');
}

}  // namespace

QString usageText() {
    QStringList families;
    for (const comm::FamilyInfo* family : comm::FamilyRegistry::instance().all()) {
        families << QStringLiteral("%1 (%2%3)")
                        .arg(family->id, family->title,
                             family->built ? QString()
                                           : QStringLiteral(", announced, not built yet"));
    }
    QStringList protocols;
    for (const comm::ProtocolInfo* protocol : comm::ProtocolRegistry::instance().all())
        protocols << QStringLiteral("%1: %2").arg(protocol->id, protocol->title);
    return QStringLiteral(
               "Usage: cambench-cli [--port PORT] [--family FAMILY] [--protocol PROTOCOL] [--baud "
               "N]\n"
               "                    %4\n"
               "                    [--timeout MS] [--log FILE] COMMAND\n"
               "       cambench-cli help COMMAND      the lines below about COMMAND\n"
               "\n"
               "Every option may come before or after COMMAND. The family follows from the\n"
               "command (mc: mc1, c3: compax3), from a family's own option (--axes,\n"
               "--dictionary ...) or one only its protocols take (below), from --protocol or\n"
               "from a port that names its protocol (sim:protocol=3964r-n96); two that name\n"
               "different families are an error naming both.\n"
               "\n"
               "PORT: /dev/ttyUSB0, COM3, tcp://HOST:PORT, or sim (built-in simulated device; the "
               "default)\n"
               "  --family      %1;\n"
               "                the first is the default; the protocol follows the family\n"
               "  --protocol    a protocol of the family (default: its first):\n"
               "                %2\n"
               "  --baud N      line speed; overrides the protocol's default\n"
               "%5"
               "  --timeout MS  reply timeout per attempt (default: derived from the baud rate)\n"
               "  --log FILE    write the traffic (hex and ASCII, user numbers masked) to FILE\n"
               "\n"
               "Commands for every family:\n"
               "  help [COMMAND]                   this help, or its lines about COMMAND\n"
               "  ports [--json]                   serial ports of this PC with their USB adapter\n"
               "                                   (description, manufacturer, S/N, VID:PID)\n"
               "  detect [--json]                  what answers on --port: each family's "
               "protocols\n"
               "                                   tried at their default line settings\n"
               "  check [--json] [-o FILE]         try each provisional reading of ours on the\n"
               "                                   device, reading only: held, refuted (what it\n"
               "                                   answered instead) or could not tell; exit 1\n"
               "                                   when any was refuted. Send the report back.\n"
               "                                   It tries the tables in use, or the device's "
               "own:\n"
               "                                   mc1 --parameters FILE, compax3 --dictionary "
               "FILE\n"
               "  machine status FILE [--json]     each device of a machine file (name, family,\n"
               "                                   port and its options): its identity, or why\n"
               "                                   not; exit 3 when any did not answer, 4 when\n"
               "                                   another device answers than the file records\n"
               "  machine backup FILE -o DIR [--resume] [--replacement NAME,...]\n"
               "                 [--operator NAME] [-m NOTE]\n"
               "                                   each device by its family's backup part into "
               "DIR\n"
               "                                   (with machine.json and manifest.json: who, "
               "why,\n"
               "                                   tool version; identity, file, SHA-256, time,\n"
               "                                   result per device); exit 0 only when every\n"
               "                                   device was saved; FILE records each identity\n"
               "                                   first seen; another device than FILE records\n"
               "                                   is not saved unless --replacement\n"
               "  machine verify DIR [--replacement NAME,...]\n"
               "                                   each device against its file, each difference\n"
               "                                   in its family's terms; exit 1 when one "
               "differs,\n"
               "                                   3 when one was not verified, 4 when another\n"
               "                                   device answers\n"
               "  machine diff DIR1 DIR2           two backups of the machine, device by device,\n"
               "                                   no device asked; exit 1 when they differ\n"
               "  machine restore DIR [--only NAME,...] [--replacement NAME,...] [--plan]\n"
               "                 [--operator NAME] [-m NOTE]\n"
               "                                   each device by its family's restore, with that\n"
               "                                   family's checks first; only to the device each\n"
               "                                   file was taken from (else nothing is written "
               "to\n"
               "                                   it, exit 4), or to the replacement of NAME;\n"
               "                                   safety copies go beside DIR; --plan: what\n"
               "                                   would be written, nothing written\n"
               "                                   The machine commands take devices on different\n"
               "                                   ports at once (those sharing a port one after\n"
               "                                   the other); each device's lines are printed\n"
               "                                   whole, in the file's order\n"
               "%3"
               "\n"
               "Writes are checked against the connected device before the first byte (nothing is\n"
               "sent when anything does not fit); then every item is reported: written, "
               "unchanged,\n"
               "failed (the device keeps its value), changed though the write failed (with what "
               "the\n"
               "device now holds), or not sent. Exit 0 only when every item was written or "
               "unchanged.\n"
               "\n"
               "Outputs and inputs count from 1, programs from 0.\n"
               "Exit codes: 0 ok; 1 the device answered with an error or cannot do what was asked\n"
               "            (its protocol or variant lacks it, it is not the --variant given; an\n"
               "            item not sent for that reason), verify: the device differs; 2 a "
               "command\n"
               "            line that cannot be understood; 3 communication failure; 4 an invalid\n"
               "            file or value, or one that does not fit the device\n")
        .arg(families.join(QStringLiteral(";\n                ")),
             protocols.join(QStringLiteral("\n                ")),
             CommandRegistry::instance().help(), protocolOptionsUsage(), protocolOptionsHelp());
}

}  // namespace cambench::cli
