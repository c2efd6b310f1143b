// `machine backup FILE -o DIR`, `machine verify DIR`, `machine restore DIR`:
// each device of the machine by its family's own command (the verbs each
// family registers: the CamCon's EEPROM image, the MC-1 backup, the Compax3
// parameter set), one device after the other. DIR holds the machine file as
// given (machine.json), one file per device and manifest.json, rewritten
// after each device: machine, and per device its name, family, identity,
// file, SHA-256, time and result. Names no family.
#include "machine_command.h"

#include "cli_output.h"
#include "cli_session.h"
#include "commands.h"
#include "exit_codes.h"

#include "model/atomic_file.h"
#include "model/file_read.h"
#include "model/json_file.h"

#include <QCryptographicHash>
#include <QDateTime>
#include <QDir>
#include <QJsonArray>
#include <QJsonObject>
#include <QRegularExpression>

#include <functional>

namespace cambench::cli {

namespace {

const JsonFileType kManifest{"cambench-machine-backup", 1, "machine backup manifest"};
const QString kMachineFileName = QStringLiteral("machine.json");
const QString kManifestName = QStringLiteral("manifest.json");

QString exitText(int code) {
    switch (code) {
        case ExitDevice:
            return QStringLiteral("exit 1: the device refused or differs");
        case ExitUsage:
            return QStringLiteral("exit 2: the family's command does not fit this device");
        case ExitCommunication:
            return QStringLiteral("exit 3: not reached or the line failed");
        case ExitInvalidData:
            return QStringLiteral("exit 4: a file or value failed its check");
        default:
            return QStringLiteral("exit %1").arg(code);
    }
}

// The device's file in DIR: its name with anything but letters, digits,
// '.', '-' and '_' as '_' (a name may hold a slash).
QString fileNameOf(const MachineDevice& device) {
    QString name = device.name;
    name.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9._-]")), QStringLiteral("_"));
    return name + QStringLiteral(".json");
}

QString sha256Of(const QString& path) {
    const Result<QByteArray> bytes = readFileBytes(path);
    return bytes ? QString::fromLatin1(
                       QCryptographicHash::hash(*bytes, QCryptographicHash::Sha256).toHex())
                 : QString();
}

// Runs the family's `verb` words ({file} replaced) on `session`; the exit code.
int runFamilyVerb(CliSession& session, const QString& family, QStringList words,
                  const QString& file) {
    for (QString& word : words) word.replace(QLatin1String("{file}"), file);
    const CommandGroup* group = CommandRegistry::instance().find(family, words.value(0));
    if (!group) return ExitUsage;
    CommandArgs args(words.value(0), words.mid(1));
    return group->run(session, args);
}

// The machine file and the manifest a backup left in `dir`.
struct MachineFolder {
    MachineSetup setup;
    QHash<QString, QJsonObject> entries;  // by device name
};

Result<MachineFolder> loadFolder(const QString& dir) {
    const QString machinePath = QDir(dir).filePath(kMachineFileName);
    const Result<QByteArray> machineBytes = readFileBytes(machinePath);
    if (!machineBytes)
        return Error::invalidData(
            QStringLiteral("%1 is no machine backup folder: %2 (made by `machine backup`)")
                .arg(dir, machineBytes.error().message));
    Result<MachineSetup> setup = loadMachine(*machineBytes, machinePath);
    if (!setup) return setup.error();
    const Result<QByteArray> manifestBytes = readFileBytes(QDir(dir).filePath(kManifestName));
    if (!manifestBytes) return manifestBytes.error();
    const Result<QJsonObject> manifest = parseJsonFile(*manifestBytes, kManifest);
    if (!manifest) return manifest.error();
    MachineFolder folder{*setup, {}};
    for (const QJsonValue& value : manifest->value(QStringLiteral("devices")).toArray()) {
        const QJsonObject entry = value.toObject();
        folder.entries.insert(entry.value(QStringLiteral("name")).toString(), entry);
    }
    return folder;
}

Status writeManifest(const QString& dir, const QString& machine, const QJsonArray& devices) {
    QJsonObject root = jsonFileHeader(kManifest);
    root.insert(QStringLiteral("machine"), machine);
    root.insert(QStringLiteral("devices"), devices);
    return writeFileAtomically(QDir(dir).filePath(kManifestName), toIndentedJson(root));
}

// An entry of an earlier run that still holds: saved, and its file unchanged.
bool stillSaved(const QJsonObject& entry, const QString& dir) {
    return entry.value(QStringLiteral("result")).toString() == QLatin1String("saved") &&
           sha256Of(QDir(dir).filePath(entry.value(QStringLiteral("file")).toString())) ==
               entry.value(QStringLiteral("sha256")).toString();
}

QJsonObject backUp(const MachineDevice& device, const GlobalOptions& options, const QString& dir) {
    QJsonObject entry{{QStringLiteral("name"), device.name},
                      {QStringLiteral("family"), device.family},
                      {QStringLiteral("file"), fileNameOf(device)}};
    const MachineVerbs* verbs = CommandRegistry::instance().machineVerbs(device.family);
    CliSession session(options);
    printOut(QStringLiteral("== %1 (%2, %3)\n").arg(device.name, device.family, session.where()));
    if (!verbs) {
        entry.insert(QStringLiteral("result"),
                     QStringLiteral("failed: the %1 family has no backup").arg(device.family));
        return entry;
    }
    const Result<QString> identity = identifyMachineDevice(session, device.name);
    if (!identity) {
        reportError(identity.error());
        entry.insert(QStringLiteral("result"),
                     QStringLiteral("failed: not reached: %1").arg(identity.error().message));
        return entry;
    }
    entry.insert(QStringLiteral("identity"), *identity);
    const QString path = QDir(dir).filePath(fileNameOf(device));
    const int code = runFamilyVerb(session, device.family, verbs->backup, path);
    entry.insert(QStringLiteral("time"),
                 QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs));
    if (code != ExitOk) {
        entry.insert(QStringLiteral("result"), QStringLiteral("failed: %1").arg(exitText(code)));
        return entry;
    }
    entry.insert(QStringLiteral("sha256"), sha256Of(path));
    entry.insert(QStringLiteral("result"), QStringLiteral("saved"));
    return entry;
}

}  // namespace

int runMachineBackup(const MachineSetup& setup, const QByteArray& machineFile, const QString& dir,
                     bool resume) {
    if (!QDir().mkpath(dir))
        return reportError(Error::communication(
            QStringLiteral("cannot make the folder %1; check the path and its rights").arg(dir)));
    QHash<QString, QJsonObject> earlier;
    if (resume) {
        const Result<MachineFolder> folder = loadFolder(dir);
        if (folder) earlier = folder->entries;
    }
    if (const Status saved = writeFileAtomically(QDir(dir).filePath(kMachineFileName), machineFile);
        !saved)
        return reportError(saved.error());
    QJsonArray devices;
    int saved = 0;
    for (int i = 0; i < setup.machine.devices.size(); ++i) {
        const MachineDevice& device = setup.machine.devices.at(i);
        const QJsonObject before = earlier.value(device.name);
        if (resume && stillSaved(before, dir)) {
            printOut(QStringLiteral("== %1: kept from the earlier run (%2)\n")
                         .arg(device.name, before.value(QStringLiteral("time")).toString()));
            devices << before;
        } else {
            devices << backUp(device, setup.options.at(i), dir);
        }
        if (devices.last().toObject().value(QStringLiteral("result")).toString() ==
            QLatin1String("saved"))
            ++saved;
        // Rewritten after each device: an interrupted backup says what it has.
        if (const Status written = writeManifest(dir, setup.machine.machine, devices); !written)
            return reportError(written.error());
    }
    printOut(QStringLiteral("%1: %2 of %3 devices saved in %4\n")
                 .arg(setup.machine.machine)
                 .arg(saved)
                 .arg(setup.machine.devices.size())
                 .arg(dir));
    for (const QJsonValue& value : devices) {
        const QJsonObject entry = value.toObject();
        if (entry.value(QStringLiteral("result")).toString() != QLatin1String("saved"))
            printOut(QStringLiteral("NOT SAVED: %1: %2\n")
                         .arg(entry.value(QStringLiteral("name")).toString(),
                              entry.value(QStringLiteral("result")).toString()));
    }
    return saved == setup.machine.devices.size() ? ExitOk : ExitCommunication;
}

namespace {

// Runs `verb` of each device the folder saved (and `only` names, when
// given); `says(code)` words each device's outcome. The worst exit code.
int forEachSaved(const QString& dir, const QStringList& only, QStringList MachineVerbs::*verb,
                 const std::function<QString(int)>& says,
                 const std::function<int(const QList<int>&)>& exitFor) {
    const Result<MachineFolder> folder = loadFolder(dir);
    if (!folder) return reportError(folder.error());
    for (const QString& name : only)
        if (!folder->setup.machine.device(name))
            return reportError(Error::usage(
                QStringLiteral("--only %1: the machine has no device of that name").arg(name)));
    QList<int> codes;
    QStringList lines;
    for (int i = 0; i < folder->setup.machine.devices.size(); ++i) {
        const MachineDevice& device = folder->setup.machine.devices.at(i);
        if (!only.isEmpty() && !only.contains(device.name)) continue;
        const QJsonObject entry = folder->entries.value(device.name);
        const MachineVerbs* verbs = CommandRegistry::instance().machineVerbs(device.family);
        if (!stillSaved(entry, dir) || !verbs) {
            lines << QStringLiteral("%1: not in the backup or its file changed since")
                         .arg(device.name);
            codes << ExitInvalidData;
            continue;
        }
        CliSession session(folder->setup.options.at(i));
        printOut(
            QStringLiteral("== %1 (%2, %3)\n").arg(device.name, device.family, session.where()));
        const int code =
            runFamilyVerb(session, device.family, (*verbs).*verb,
                          QDir(dir).filePath(entry.value(QStringLiteral("file")).toString()));
        codes << code;
        lines << QStringLiteral("%1: %2").arg(device.name, says(code));
    }
    printOut(QStringLiteral("%1:\n%2\n").arg(folder->setup.machine.machine, lines.join('\n')));
    return exitFor(codes);
}

}  // namespace

int runMachineVerify(const QString& dir) {
    return forEachSaved(
        dir, {}, &MachineVerbs::verify,
        [](int code) {
            return code == ExitOk       ? QStringLiteral("equal")
                   : code == ExitDevice ? QStringLiteral("DIFFERS")
                                        : QStringLiteral("NOT VERIFIED (%1)").arg(exitText(code));
        },
        [](const QList<int>& codes) {
            // Exit 1 when a device differs; a device not verified is worse.
            int worst = ExitOk;
            for (int code : codes)
                if (code != ExitOk && code != ExitDevice) worst = code;
            return worst != ExitOk ? worst : codes.contains(ExitDevice) ? ExitDevice : ExitOk;
        });
}

int runMachineRestore(const QString& dir, const QStringList& only) {
    return forEachSaved(
        dir, only, &MachineVerbs::restore,
        [](int code) {
            return code == ExitOk ? QStringLiteral("restored")
                                  : QStringLiteral("NOT RESTORED (%1)").arg(exitText(code));
        },
        [](const QList<int>& codes) {
            for (int code : codes)
                if (code != ExitOk) return code;
            return int(ExitOk);
        });
}

}  // namespace cambench::cli
