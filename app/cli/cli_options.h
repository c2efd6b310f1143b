#pragma once

#include "comm/device/protocol_options.h"
#include "comm/device/protocol_registry.h"
#include "model/result.h"

#include <QString>
#include <QStringList>

namespace cambench::cli {

// The options of the shell and the command they go with (see usageText()):
// before or after COMMAND alike.
struct GlobalOptions {
    QString port = QStringLiteral("sim");
    // A FamilyRegistry id: the one --family, --protocol, the port, the
    // command, a family's option or a protocol's option names; without
    // any, FamilyRegistry::defaultId().
    QString family;
    // A ProtocolRegistry id of `family`: --protocol, else the one the port
    // names, else the command's or the family's default when it takes the
    // protocol options given, else the family's first that does (--address
    // asks for a bus whose devices have addresses).
    QString protocol;
    int baud = 0;       // 0 = the protocol's default
    int timeoutMs = 0;  // 0 = derived from the line
    bool timeoutGiven = false;
    QString logFile;
    // The options protocols declare (--device, --pc-number, --address,
    // --variant: ProtocolInfo::options), as typed, checked against `protocol`.
    comm::OptionValues protocolValues;
    QString command;
    // The command's own words and options (those given before COMMAND too)
    // and the families' options (--axes, --dictionary: CommandRegistry::option).
    QStringList commandArgs;

    const comm::ProtocolInfo& protocolInfo() const;  // parseGlobalOptions checked the id
    int effectiveBaud() const;
    bool isBus() const { return protocolInfo().isBus; }
    // The line and the protocol settings these options describe.
    comm::ConnectionSettings connection() const;
    comm::ProtocolSettingsPtr protocolSettings() const;
};

// Parses argv (without the program name): the shell's and the families'
// options anywhere, the first other word is COMMAND. Fails with
// ErrorKind::Usage, also for a family not built yet and for two words that
// name different families (--family and a command of another) or protocols.
Result<GlobalOptions> parseGlobalOptions(const QStringList& args);

// The arguments of one command: options and positionals, consumed one by one;
// finish() rejects whatever is left over.
class CommandArgs {
public:
    CommandArgs(QString command, QStringList args)
        : m_command(std::move(command)), m_args(std::move(args)) {}

    const QString& command() const { return m_command; }

    bool takeFlag(const QString& name);
    // Value of `--name VALUE`, `--name=VALUE` (or a short alias `-o VALUE`).
    Result<QString> takeOption(const QString& name, const QString& shortName = {});
    Result<int> takeIntOption(const QString& name, int fallback, int min, int max);
    // The next word that is not an option; empty when there is none.
    QString takePositional();
    Result<QString> takeRequiredPositional(const QString& what);
    Status finish() const;

private:
    QString m_command;
    QStringList m_args;
};

// Parses a whole decimal number in [min,max] with a usage error naming `what`.
Result<int> parseIntArgument(const QString& text, const QString& what, int min, int max);

// Device numbers "0,5,7" (each 0..63, no duplicates) with a usage error naming `what`.
Result<QList<int>> parseDeviceNumbers(const QString& text, const QString& what);

QString usageText();

}  // namespace cambench::cli
