// `machine status FILE` and the dispatch of the machine commands: each
// device of a machine file (model/machine/machine_file.h) is reached with its
// own options, as `cambench-cli --family F --port P ...` would reach it.
// Names no family: the device's family and protocol come from the file,
// checked by the same option parser as the command line's.
#include "machine_command.h"

#include "cli_output.h"
#include "commands.h"
#include "exit_codes.h"
#include "machine_history.h"
#include "machine_parallel.h"

#include "comm/device/device_connection.h"
#include "comm/usecases/machine_backup.h"
#include "model/file_read.h"
#include "model/machine/machine_file.h"

#include "cambench_version.h"

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
    Result<usecases::DeviceAnswer> identity = usecases::DeviceAnswer{};
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
    status.identity = session.run<comm::DeviceConnection, usecases::DeviceAnswer>(
        QStringLiteral("identify %1").arg(device.name),
        [](comm::DeviceConnection& connection, comm::JobContext&) {
            return usecases::whoAnswers(connection);
        });
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
    return machineSetup(*machine, where);
}

Result<MachineSetup> machineSetup(const MachineFile& machine, const QString& where) {
    MachineSetup setup{machine, {}};
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

namespace {

QStringList namesOf(const QString& list) {
    return list.split(QLatin1Char(','), Qt::SkipEmptyParts);
}

}  // namespace

// --operator NAME (default: the login name) and -m NOTE, with this build's
// version and revision.
Result<BackupAuthor> takeAuthor(CommandArgs& args) {
    const Result<QString> operatorName = args.takeOption(QStringLiteral("--operator"));
    if (!operatorName) return operatorName.error();
    const Result<QString> note = args.takeOption(QStringLiteral("--message"), QStringLiteral("-m"));
    if (!note) return note.error();
    return BackupAuthor{operatorName->isEmpty() ? loginName() : *operatorName, *note,
                        QStringLiteral(CAMBENCH_VERSION_NUMBER), QStringLiteral(CAMBENCH_REVISION)};
}

int runMachine(CliSession&, CommandArgs& args) {
    const Result<QString> verb = takeVerb(
        args, {QStringLiteral("status"), QStringLiteral("backup"), QStringLiteral("verify"),
               QStringLiteral("restore"), QStringLiteral("diff"), QStringLiteral("history"),
               QStringLiteral("release"), QStringLiteral("watch")});
    if (!verb) return reportError(verb.error());
    const auto is = [&verb](const char* name) { return *verb == QLatin1String(name); };
    if (is("history") || is("release") || is("watch")) return runMachineHistoryVerb(*verb, args);
    if (is("diff")) {
        const Result<QString> first =
            args.takeRequiredPositional(QStringLiteral("the first backup folder"));
        if (!first) return reportError(first.error());
        // An archive: machine diff DIR [A [B]], versions of it (issue 37).
        if (isMachineArchive(*first)) {
            QStringList versions;
            for (int i = 0; i < 2; ++i)
                if (const QString version = args.takePositional(); !version.isEmpty())
                    versions << version;
            if (const Status done = args.finish(); !done) return reportError(done.error());
            return runMachineVersionDiff(*first, versions);
        }
        const Result<QString> second =
            args.takeRequiredPositional(QStringLiteral("the second backup folder"));
        if (!second) return reportError(second.error());
        if (const Status done = args.finish(); !done) return reportError(done.error());
        return runMachineDiff(*first, *second);
    }
    const bool onFolder = is("verify") || is("restore");
    const Result<QString> path =
        args.takeRequiredPositional(onFolder ? QStringLiteral("the machine's backup folder")
                                             : QStringLiteral("the machine file"));
    if (!path) return reportError(path.error());
    const bool json = is("status") && args.takeFlag(QStringLiteral("--json"));
    MachineRun run;
    run.machinePath = *path;
    run.resume = is("backup") && args.takeFlag(QStringLiteral("--resume"));
    run.planOnly = is("restore") && args.takeFlag(QStringLiteral("--plan"));
    if (is("backup")) {
        const Result<QString> dir =
            args.takeOption(QStringLiteral("--output"), QStringLiteral("-o"));
        if (!dir) return reportError(dir.error());
        const Result<QString> archive = args.takeOption(QStringLiteral("--archive"));
        if (!archive) return reportError(archive.error());
        if (dir->isEmpty() == archive->isEmpty())
            return reportError(Error::usage(
                QStringLiteral("machine backup needs -o DIR, the folder to fill, or --archive "
                               "DIR, the machine's archive (one of them)")));
        run.dir = *dir;
        run.archive = *archive;
    }
    if (is("backup") || is("restore")) {
        const Result<BackupAuthor> author = takeAuthor(args);
        if (!author) return reportError(author.error());
        run.author = *author;
    }
    if (is("restore")) {
        const Result<QString> only = args.takeOption(QStringLiteral("--only"));
        if (!only) return reportError(only.error());
        run.only = namesOf(*only);
    }
    QString version;
    if (is("restore")) {
        const Result<QString> named = args.takeOption(QStringLiteral("--version"));
        if (!named) return reportError(named.error());
        version = *named;
    }
    if (!is("status")) {
        const Result<QString> replacement = args.takeOption(QStringLiteral("--replacement"));
        if (!replacement) return reportError(replacement.error());
        run.replacements = namesOf(*replacement);
    }
    if (const Status done = args.finish(); !done) return reportError(done.error());

    if (is("verify")) return runMachineVerify(*path, run.replacements);
    if (is("restore") && !version.isEmpty()) return runMachineVersionRestore(*path, version, run);
    if (is("restore") && isMachineArchive(*path))
        return reportError(Error::usage(
            QStringLiteral("%1 is a machine archive: name the version to restore with --version "
                           "ID (a commit id or a prefix, a tag, or \"released\")")
                .arg(*path)));
    if (is("restore")) return runMachineRestore(*path, run);
    const Result<QByteArray> bytes = readFileBytes(*path);
    if (!bytes) return reportError(bytes.error());
    // Every device's options are checked before the first device is asked.
    const Result<MachineSetup> setup = loadMachine(*bytes, *path);
    if (!setup) return reportError(setup.error());
    if (const Status names =
            checkDeviceNames(setup->machine, run.replacements, QStringLiteral("--replacement"));
        !names)
        return reportError(names.error());
    if (is("status")) return runMachineStatus(*setup, json);
    return run.archive.isEmpty() ? runMachineBackup(*setup, run)
                                 : runMachineArchiveBackup(*setup, run);
}

}  // namespace cambench::cli
