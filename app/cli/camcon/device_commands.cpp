// info, status, scan, raw, users: commands that only read and print.
#include "app/cli/camcon/camcon_commands.h"
#include "app/cli/camcon/cli_format.h"
#include "app/cli/cli_output.h"
#include "app/cli/exit_codes.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace cambench::cli {

namespace {

using comm::CamConDevice;
using comm::JobContext;

// Device numbers answer within a few milliseconds; without --timeout a scan
// of all 64 numbers stays short.

// The device status tables list every possible output and input; only the
// ones that are on are printed.
constexpr int kMaxPoints = 256;

QString errorStateText(int state) {
    switch (state) {
        case 0:
            return QStringLiteral("ok");
        case 1:
        case 2:
        case 3:
            return QStringLiteral("actual-value error %1").arg(state);
        case 4:
            return QStringLiteral("output error");
        case 0xFF:
            return QStringLiteral("EEPROM checksum error");
        default:
            return QStringLiteral("unknown error %1").arg(state);
    }
}

QString busUserKindText(comm::BusUser::Kind kind) {
    switch (kind) {
        case comm::BusUser::CamCon:
            return QStringLiteral("CamCon");
        case comm::BusUser::ThisPc:
            return QStringLiteral("this PC");
        case comm::BusUser::Other:
            break;
    }
    return QStringLiteral("other");
}

}  // namespace

int runInfo(CliSession& session, CommandArgs& args) {
    const bool json = args.takeFlag(QStringLiteral("--json"));
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const Result<DeviceInfo> info = runOnCamCon<DeviceInfo>(
        session, QStringLiteral("info"),
        [](CamConDevice& client, JobContext&) { return client.readInfo(); });
    if (!info) return reportError(info.error());
    if (json) return printJson(QJsonDocument(deviceInfoJson(*info)));
    printOut(keyValueLines(deviceInfoEntries(*info)));
    return ExitOk;
}

int runStatus(CliSession& session, CommandArgs& args) {
    const bool json = args.takeFlag(QStringLiteral("--json"));
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const Result<DeviceStatus> status = runOnCamCon<DeviceStatus>(
        session, QStringLiteral("status"), [](CamConDevice& client, JobContext&) {
            return client.readStatus(kMaxPoints, kMaxPoints);
        });
    if (!status) return reportError(status.error());
    const QList<int> outputs = onNumbers(status->outputs);
    const QList<int> inputs = onNumbers(status->inputs);
    if (json) {
        QJsonObject object{{QStringLiteral("position"), status->position},
                           {QStringLiteral("positionText"), status->positionText},
                           {QStringLiteral("speed"), status->speed},
                           {QStringLiteral("speedText"), status->speedText},
                           {QStringLiteral("program"), status->activeProgram},
                           {QStringLiteral("errorState"), status->errorState},
                           {QStringLiteral("error"), errorStateText(status->errorState)},
                           {QStringLiteral("outputsOn"), jsonNumbers(outputs)},
                           {QStringLiteral("inputsOn"), jsonNumbers(inputs)}};
        return printJson(QJsonDocument(object));
    }
    printOut(keyValueLines({
        {QStringLiteral("position"), status->position},
        {QStringLiteral("positionText"), status->positionText},
        {QStringLiteral("speed"), status->speed},
        {QStringLiteral("speedText"), status->speedText},
        {QStringLiteral("program"), status->activeProgram},
        {QStringLiteral("error"), errorStateText(status->errorState)},
        {QStringLiteral("outputsOn"), numberList(outputs)},
        {QStringLiteral("inputsOn"), numberList(inputs)},
    }));
    return ExitOk;
}

int runScan(CliSession& session, CommandArgs& args) {
    const bool json = args.takeFlag(QStringLiteral("--json"));
    if (const Status done = args.finish(); !done) return reportError(done.error());
    if (!session.options().isBus()) {
        return reportError(Error::unsupported(
            QStringLiteral("scan needs a bus protocol; the %1 protocol has no bus: use "
                           "--protocol multiuser (or cambus)")
                .arg(session.options().protocol)));
    }
    session.setShowProgress(true);
    const Result<comm::BusUsers> found = runOnCamCon<comm::BusUsers>(
        session, QStringLiteral("scan"),
        [](CamConDevice& device, JobContext& job) -> Result<comm::BusUsers> {
            return device.scanUsers([&job](qint64 done, qint64 total) {
                job.progress(done, total, QStringLiteral("scanning"));
            });
        });
    if (!found) return reportError(found.error());
    if (!found->kindsKnown) {
        // Multiuser: the CamCons that answered, one number a line.
        QList<int> numbers;
        for (const comm::BusUser& user : found->users) numbers << user.number;
        if (json) return printJson(QJsonDocument(jsonNumbers(numbers)));
        QString text;
        for (int device : numbers) text += QStringLiteral("%1\n").arg(device);
        printOut(text);
        return ExitOk;
    }
    // A token bus: every user, "3: CamCon", "12: other", "63: this PC".
    QJsonArray users;
    QString text;
    for (const comm::BusUser& user : found->users) {
        const QString kind = busUserKindText(user.kind);
        QJsonObject entry{{QStringLiteral("number"), user.number}, {QStringLiteral("kind"), kind}};
        if (user.silent) entry.insert(QStringLiteral("silent"), true);
        users.append(entry);
        text += QStringLiteral("%1: %2%3\n")
                    .arg(user.number)
                    .arg(kind, user.silent ? QStringLiteral(" (silent)") : QString());
    }
    if (json) return printJson(QJsonDocument(users));
    printOut(text);
    return ExitOk;
}

int runRaw(CliSession& session, CommandArgs& args) {
    const Result<QString> command =
        args.takeRequiredPositional(QStringLiteral("a COMMAND such as \"?IFGWG\""));
    if (!command) return reportError(command.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const QByteArray bytes = command->toLatin1();
    if (bytes.size() < 2 || (bytes.at(0) != '?' && bytes.at(0) != '!')) {
        return reportError(Error::usage(
            QStringLiteral("raw needs a command that starts with '?' or '!', such as \"?IFGWG\"; "
                           "the checksum is added")));
    }
    const Result<QByteArray> reply =
        runOnCamCon<QByteArray>(session, QStringLiteral("raw"),
                                [bytes](CamConDevice& device, JobContext&) -> Result<QByteArray> {
                                    if (!device.has(comm::CamConCapability::Terminal))
                                        return device.missing(comm::CamConCapability::Terminal);
                                    return device.raw(bytes);
                                });
    if (!reply) return reportError(reply.error());
    printOut(printableBytes(*reply) + u'\n');
    return ExitOk;
}

int runUsers(CliSession& session, CommandArgs& args) {
    const Result<QString> verb = takeVerb(args, {QStringLiteral("list")});
    if (!verb) return reportError(verb.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const Result<QList<User>> users = runOnCamCon<QList<User>>(
        session, QStringLiteral("users"),
        [](CamConDevice& client, JobContext&) { return client.readUsers(); });
    if (!users) return reportError(users.error());
    QString text;
    for (const User& user : *users) {
        // The number is an access code: only its mask is ever printed.
        text += QStringLiteral("%1\tnumber %2\trights: %3\toutputs: %4\n")
                    .arg(user.name, user.maskedNumber(), rightsText(user.rights),
                         user.allOutputs ? QStringLiteral("all")
                                         : numberList(onNumbers(user.outputAccess)));
    }
    printOut(text);
    return ExitOk;
}

}  // namespace cambench::cli
