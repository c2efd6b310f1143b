#pragma once

#include "comm/device/protocol_registry.h"
#include "model/result.h"

#include <QString>
#include <QStringList>

namespace cambench::cli {

// The options before COMMAND (see usageText()).
struct GlobalOptions {
    QString port = QStringLiteral("sim");
    QString family;    // a FamilyRegistry id; empty: FamilyRegistry::defaultId()
    QString protocol;  // a ProtocolRegistry id of `family`: its default unless --protocol
    int baud = 0;      // 0 = the protocol's default
    int device = 0;    // --device (CamCon Multiuser, 0..63) or --address (Compax3 RS485, 0..99)
    bool addressGiven = false;
    int pcNumber = 63;
    int timeoutMs = 0;  // 0 = derived from the line
    bool timeoutGiven = false;
    QString logFile;
    QString variant;  // --variant: a key of the protocol's variantKeys(); empty: its default
    QString command;
    QStringList commandArgs;  // everything after COMMAND

    const comm::ProtocolInfo& protocolInfo() const;  // parseGlobalOptions checked the id
    int effectiveBaud() const;
    bool isBus() const { return protocolInfo().isBus; }
    // The line and the protocol settings these options describe.
    comm::ConnectionSettings connection() const;
    comm::ProtocolSettingsPtr protocolSettings() const;
};

// Parses argv (without the program name). Fails with ErrorKind::Usage, also
// for a family not built yet and a protocol of another family.
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
