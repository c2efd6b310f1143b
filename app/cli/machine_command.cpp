// `machine status FILE` and the dispatch of the machine commands: each
// device of a machine file (model/machine/machine_file.h) is reached with its
// own options, as `cambench-cli --family F --port P ...` would reach it.
// Names no family: the device's family and protocol come from the file,
// checked by the same option parser as the command line's.
#include "machine_command.h"

#include "cli_output.h"
#include "commands.h"
#include "exit_codes.h"
#include "machine_parallel.h"

#include "comm/device/device_connection.h"
#include "model/file_read.h"
#include "model/machine/machine_file.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <vector>

namespace cambench::cli {

namespace {

struct DeviceStatus {
    QString name;
    QString family;
    QString where;
    Result<MachineDeviceIdentity> identity = MachineDeviceIdentity{};
    // "another device answers: expected ..., found ..." when the file
    // records another identity than the one that answered.
    QString another;
};

// The options of `device` as the command line parses them; a wrong family,
// protocol or value is said naming the device.
Result<GlobalOptions> deviceOptions(const MachineDevice& device, const QString& file) {
    Result<GlobalOptions> options =
        parseGlobalOptions(device.arguments() << QStringLiteral("machine"));
    if (!options)
        return Error::invalidData(QStringLiteral("Machine file %1, device %2: %3")
                                      .arg(file, device.name, options.error().message));
    return options;
}

DeviceStatus statusOf(const MachineDevice& device, const GlobalOptions& options) {
    CliSession session(options);
    DeviceStatus status;
    status.name = device.name;
    status.family = device.family;
    status.where = session.where();
    status.identity = identifyMachineDevice(session, device.name);
    if (status.identity && device.identity.known() && status.identity->identity != device.identity)
        status.another = anotherDeviceText(device.identity, status.identity->identity);
    return status;
}

// What the status line says of the device.
QString statusText(const DeviceStatus& status) {
    if (!status.identity)
        return QStringLiteral("NOT REACHED: %1").arg(status.identity.error().message);
    if (!status.another.isEmpty())
        return QStringLiteral("ANOTHER DEVICE: %1 (%2)").arg(status.another, status.identity->text);
    return status.identity->text;
}

QJsonObject statusJson(const DeviceStatus& status) {
    QJsonObject entry{{QStringLiteral("name"), status.name},
                      {QStringLiteral("family"), status.family},
                      {QStringLiteral("port"), status.where}};
    if (status.identity) {
        entry.insert(QStringLiteral("identity"), status.identity->text);
        entry.insert(QStringLiteral("recorded"), status.identity->identity.toJson());
        if (!status.another.isEmpty()) entry.insert(QStringLiteral("error"), status.another);
    } else {
        entry.insert(QStringLiteral("error"), status.identity.error().message);
    }
    return entry;
}

}  // namespace

Result<MachineDeviceIdentity> identifyMachineDevice(CliSession& session, const QString& name) {
    return session.run<comm::DeviceConnection, MachineDeviceIdentity>(
        QStringLiteral("identify %1").arg(name),
        [](comm::DeviceConnection& connection, comm::JobContext&) -> Result<MachineDeviceIdentity> {
            const Result<QString> text = connection.identify();
            if (!text) return text.error();
            const Result<DeviceIdentity> identity = connection.readIdentity();
            if (!identity) return identity.error();
            return MachineDeviceIdentity{*text, *identity};
        });
}

Status checkDeviceNames(const MachineFile& machine, const QStringList& names,
                        const QString& option) {
    for (const QString& name : names)
        if (!machine.device(name))
            return Error::usage(
                QStringLiteral("%1 %2: the machine has no device of that name").arg(option, name));
    return success();
}

Result<MachineSetup> loadMachine(const QByteArray& bytes, const QString& where) {
    Result<MachineFile> machine = parseMachineFile(bytes, where);
    if (!machine) return machine.error();
    MachineSetup setup{*machine, {}};
    for (const MachineDevice& device : setup.machine.devices) {
        const Result<GlobalOptions> parsed = deviceOptions(device, where);
        if (!parsed) return parsed.error();
        setup.options << *parsed;
    }
    return setup;
}

int runMachineStatus(const MachineSetup& setup, bool json) {
    const MachineFile& machine = setup.machine;
    const QList<GlobalOptions>& options = setup.options;
    // Devices on different ports are asked at once: a silent device's
    // retries hold up only the devices on its own port.
    std::vector<DeviceStatus> statuses(size_t(machine.devices.size()));  // a slot per thread
    QList<int> all;
    for (int i = 0; i < machine.devices.size(); ++i) all << i;
    runDevicesByPort(options, all, [&](int i) {
        statuses[size_t(i)] = statusOf(machine.devices.at(i), options.at(i));
    });
    bool allAnswered = true;
    bool anyOther = false;
    for (const DeviceStatus& status : statuses) {
        allAnswered = allAnswered && status.identity.ok();
        anyOther = anyOther || !status.another.isEmpty();
    }
    if (json) {
        QJsonArray devices;
        for (const DeviceStatus& status : statuses) devices << statusJson(status);
        printOut(QString::fromUtf8(
            QJsonDocument(QJsonObject{{QStringLiteral("machine"), machine.machine},
                                      {QStringLiteral("devices"), devices}})
                .toJson(QJsonDocument::Indented)));
    } else {
        printOut(QStringLiteral("%1\n").arg(machine.machine));
        for (const DeviceStatus& status : statuses)
            printOut(QStringLiteral("%1\t%2\t%3\t%4\n")
                         .arg(status.name, status.family, status.where, statusText(status)));
    }
    // Another device where the file records one: the file's check failed.
    return !allAnswered ? ExitCommunication : anyOther ? ExitInvalidData : ExitOk;
}

int runMachine(CliSession&, CommandArgs& args) {
    const Result<QString> verb =
        takeVerb(args, {QStringLiteral("status"), QStringLiteral("backup"),
                        QStringLiteral("verify"), QStringLiteral("restore")});
    if (!verb) return reportError(verb.error());
    const bool onFolder = *verb == QLatin1String("verify") || *verb == QLatin1String("restore");
    const Result<QString> path =
        args.takeRequiredPositional(onFolder ? QStringLiteral("the machine's backup folder")
                                             : QStringLiteral("the machine file"));
    if (!path) return reportError(path.error());
    const bool json = *verb == QLatin1String("status") && args.takeFlag(QStringLiteral("--json"));
    const bool resume =
        *verb == QLatin1String("backup") && args.takeFlag(QStringLiteral("--resume"));
    Result<QString> dir = QString();
    if (*verb == QLatin1String("backup")) {
        dir = args.takeOption(QStringLiteral("--output"), QStringLiteral("-o"));
        if (dir && dir->isEmpty())
            dir = Error::usage(QStringLiteral("machine backup needs -o DIR, the folder to fill"));
    }
    if (!dir) return reportError(dir.error());
    Result<QString> only = QString();
    if (*verb == QLatin1String("restore")) only = args.takeOption(QStringLiteral("--only"));
    if (!only) return reportError(only.error());
    Result<QString> replacement = QString();
    if (*verb != QLatin1String("status"))
        replacement = args.takeOption(QStringLiteral("--replacement"));
    if (!replacement) return reportError(replacement.error());
    const QStringList replacements = replacement->split(QLatin1Char(','), Qt::SkipEmptyParts);
    if (const Status done = args.finish(); !done) return reportError(done.error());

    if (onFolder) {
        return *verb == QLatin1String("verify")
                   ? runMachineVerify(*path, replacements)
                   : runMachineRestore(*path, only->split(QLatin1Char(','), Qt::SkipEmptyParts),
                                       replacements);
    }
    const Result<QByteArray> bytes = readFileBytes(*path);
    if (!bytes) return reportError(bytes.error());
    // Every device's options are checked before the first device is asked.
    const Result<MachineSetup> setup = loadMachine(*bytes, *path);
    if (!setup) return reportError(setup.error());
    if (const Status names =
            checkDeviceNames(setup->machine, replacements, QStringLiteral("--replacement"));
        !names)
        return reportError(names.error());
    return *verb == QLatin1String("status")
               ? runMachineStatus(*setup, json)
               : runMachineBackup(*setup, *path, *dir, resume, replacements);
}

}  // namespace cambench::cli
