// `machine backup FILE -o DIR`, `machine verify DIR`, `machine restore DIR`:
// each device of the machine by its family's own command (the verbs each
// family registers: the CamCon's EEPROM image, the MC-1 backup, the Compax3
// parameter set), devices on different ports at once (machine_parallel.h),
// each device's lines printed whole in the file's order. DIR holds the
// machine file (machine.json; at the end with each saved device's identity),
// one file per device and manifest.json, rewritten after each device:
// machine, and per device its name, family, identity (to compare) and what
// it said of itself (device), file, SHA-256, time and result. Each device
// is first asked who it is: another one than the machine file or the
// backup records is said ("another device answers: expected ..., found
// ...") and nothing is saved from it, verified or written to it unless the
// person named it with --replacement. Names no family.
#include "machine_command.h"

#include "cli_output.h"
#include "cli_session.h"
#include "commands.h"
#include "exit_codes.h"
#include "machine_parallel.h"

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
#include <optional>
#include <vector>

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

// The identity an entry of the manifest records; not known in a manifest
// older than that record (it held identify()'s text there).
DeviceIdentity recordedIdentity(const QJsonObject& entry) {
    const Result<DeviceIdentity> identity =
        DeviceIdentity::fromJson(entry.value(QStringLiteral("identity")), QString());
    return identity ? *identity : DeviceIdentity();
}

// "another device answers: ... Nothing was ... NAME." on stderr, as the
// device's own lines say it; the text for its summary line.
QString sayAnotherDevice(const QString& name, const DeviceIdentity& expected,
                         const DeviceIdentity& found, const QString& nothing) {
    const QString another = anotherDeviceText(expected, found);
    reportError(Error::invalidData(
        QStringLiteral("%1: %2. %3. Only if it replaces that device, add --replacement %1.")
            .arg(name, another, nothing)));
    return another;
}

QJsonObject backUp(const MachineDevice& device, const GlobalOptions& options, const QString& dir,
                   bool replacement) {
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
    const Result<MachineDeviceIdentity> identity = identifyMachineDevice(session, device.name);
    if (!identity) {
        reportError(identity.error());
        entry.insert(QStringLiteral("result"),
                     QStringLiteral("failed: not reached: %1").arg(identity.error().message));
        return entry;
    }
    entry.insert(QStringLiteral("identity"), identity->identity.toJson());
    entry.insert(QStringLiteral("device"), identity->text);
    if (device.identity.known() && device.identity != identity->identity && !replacement) {
        // Saved under this name, its file would later be restored into the
        // device the machine file names.
        const QString another = sayAnotherDevice(device.name, device.identity, identity->identity,
                                                 QStringLiteral("Nothing was saved from it"));
        entry.insert(QStringLiteral("result"), QStringLiteral("failed: %1").arg(another));
        return entry;
    }
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

namespace {

// The machine file with the identity each saved device answered with.
MachineFile withIdentities(MachineFile machine, const QJsonArray& devices) {
    for (const QJsonValue& value : devices) {
        const QJsonObject entry = value.toObject();
        if (entry.value(QStringLiteral("result")).toString() != QLatin1String("saved")) continue;
        for (MachineDevice& device : machine.devices)
            if (device.name == entry.value(QStringLiteral("name")).toString())
                device.identity = recordedIdentity(entry);
    }
    return machine;
}

// Records in the person's machine file each identity first seen (and the
// replacements accepted): the next status, backup or verify says when
// another device answers there. A file that cannot be written is said, and
// the backup is not failed for it.
void recordIdentities(const MachineFile& given, const MachineFile& now, const QString& path,
                      const QStringList& replacements) {
    MachineFile updated = given;
    QStringList recorded;
    for (int i = 0; i < updated.devices.size(); ++i) {
        MachineDevice& device = updated.devices[i];
        const DeviceIdentity& seen = now.devices.at(i).identity;
        if (!seen.known() || device.identity == seen) continue;
        if (device.identity.known() && !replacements.contains(device.name)) continue;
        device.identity = seen;
        recorded << device.name;
    }
    if (recorded.isEmpty()) return;
    if (const Status written = writeFileAtomically(path, machineFileJson(updated)); !written) {
        printError(QStringLiteral("note: the identities of %1 were not recorded in %2: %3")
                       .arg(recorded.join(QLatin1String(", ")), path, written.error().message));
        return;
    }
    printOut(QStringLiteral("%1 records the identity of %2 now\n")
                 .arg(path, recorded.join(QLatin1String(", "))));
}

}  // namespace

int runMachineBackup(const MachineSetup& setup, const QString& machinePath, const QString& dir,
                     bool resume, const QStringList& replacements) {
    if (!QDir().mkpath(dir))
        return reportError(Error::communication(
            QStringLiteral("cannot make the folder %1; check the path and its rights").arg(dir)));
    QHash<QString, QJsonObject> earlier;
    if (resume) {
        const Result<MachineFolder> folder = loadFolder(dir);
        if (folder) earlier = folder->entries;
    }
    // The machine file as given first: an interrupted backup still holds it.
    const QString folderMachine = QDir(dir).filePath(kMachineFileName);
    if (const Status saved = writeFileAtomically(folderMachine, machineFileJson(setup.machine));
        !saved)
        return reportError(saved.error());
    const QList<MachineDevice>& all = setup.machine.devices;
    std::vector<std::optional<QJsonObject>> entries(size_t(all.size()));  // a slot per thread
    QList<int> indices;
    for (int i = 0; i < all.size(); ++i) indices << i;
    const auto backUpOrKeep = [&](int i) {
        const QJsonObject before = earlier.value(all.at(i).name);
        if (resume && stillSaved(before, dir)) {
            printOut(QStringLiteral("== %1: kept from the earlier run (%2)\n")
                         .arg(all.at(i).name, before.value(QStringLiteral("time")).toString()));
            entries[size_t(i)] = before;
        } else {
            entries[size_t(i)] =
                backUp(all.at(i), setup.options.at(i), dir, replacements.contains(all.at(i).name));
        }
    };
    // Rewritten after each device, one at a time, with every device finished
    // so far in the file's order: an interrupted backup says what it has.
    // Only finished devices' slots are read here: the others are still being
    // written by their threads.
    Status manifest = success();
    QJsonArray devices;
    std::vector<bool> finished(size_t(all.size()), false);
    const auto recordDone = [&](int done) {
        finished[size_t(done)] = true;
        devices = {};
        for (size_t i = 0; i < entries.size(); ++i)
            if (finished[i]) devices << *entries[i];
        if (manifest) manifest = writeManifest(dir, setup.machine.machine, devices);
    };
    runDevicesByPort(setup.options, indices, backUpOrKeep, recordDone);
    if (!manifest) return reportError(manifest.error());
    const MachineFile identified = withIdentities(setup.machine, devices);
    if (const Status saved = writeFileAtomically(folderMachine, machineFileJson(identified));
        !saved)
        return reportError(saved.error());
    recordIdentities(setup.machine, identified, machinePath, replacements);
    int saved = 0;
    for (const QJsonValue& value : devices)
        if (value.toObject().value(QStringLiteral("result")).toString() == QLatin1String("saved"))
            ++saved;
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

// What became of one device in a verify or a restore: its exit code and its
// summary line.
struct DeviceOutcome {
    int code = ExitOk;
    QString line;
};

// Asks the device who it is and, when it is the one the backup recorded or
// the person accepted it (`accepted`), runs `words`; `says(code)` words the
// outcome of a family command that ran. A manifest older than the identity
// record leaves the check to the family's command (a restore refuses a
// file that records no identity unless accepted).
DeviceOutcome runChecked(CliSession& session, const MachineDevice& device, const QJsonObject& entry,
                         bool accepted, const QStringList& words, const QString& file,
                         const QString& nothing, const std::function<QString(int)>& says) {
    const DeviceIdentity expected = recordedIdentity(entry);
    if (expected.known()) {
        const Result<MachineDeviceIdentity> found = identifyMachineDevice(session, device.name);
        if (!found) {
            reportError(found.error());
            return {
                exitCodeFor(found.error().kind),
                QStringLiteral("%1: %2").arg(device.name, says(exitCodeFor(found.error().kind)))};
        }
        if (found->identity != expected && !accepted) {
            const QString another =
                sayAnotherDevice(device.name, expected, found->identity, nothing);
            return {ExitInvalidData,
                    QStringLiteral("%1: ANOTHER DEVICE: %2").arg(device.name, another)};
        }
    }
    const int code = runFamilyVerb(session, device.family, words, file);
    return {code, QStringLiteral("%1: %2").arg(device.name, says(code))};
}

// Runs `verb` of each device the folder saved (and `only` names, when
// given), each after asking it who it is (runChecked); `says(code)` words
// each device's outcome. The worst exit code.
int forEachSaved(const QString& dir, const QStringList& only, const QStringList& replacements,
                 QStringList MachineVerbs::*verb, const QString& nothing,
                 const std::function<QString(int)>& says,
                 const std::function<int(const QList<int>&)>& exitFor) {
    const Result<MachineFolder> folder = loadFolder(dir);
    if (!folder) return reportError(folder.error());
    for (const auto& [names, option] : {std::pair{only, QStringLiteral("--only")},
                                        std::pair{replacements, QStringLiteral("--replacement")}})
        if (const Status known = checkDeviceNames(folder->setup.machine, names, option); !known)
            return reportError(known.error());
    const QList<MachineDevice>& all = folder->setup.machine.devices;
    std::vector<DeviceOutcome> outcomes(size_t(all.size()));  // a slot per thread
    QList<int> saved;  // the devices to run, in the file's order
    for (int i = 0; i < all.size(); ++i) {
        const MachineDevice& device = all.at(i);
        if (!only.isEmpty() && !only.contains(device.name)) continue;
        if (!stillSaved(folder->entries.value(device.name), dir) ||
            !CommandRegistry::instance().machineVerbs(device.family)) {
            outcomes[size_t(i)] = {
                ExitInvalidData,
                QStringLiteral("%1: not in the backup or its file changed since").arg(device.name)};
            continue;
        }
        saved << i;
    }
    runDevicesByPort(folder->setup.options, saved, [&](int i) {
        const MachineDevice& device = all.at(i);
        CliSession session(folder->setup.options.at(i));
        printOut(
            QStringLiteral("== %1 (%2, %3)\n").arg(device.name, device.family, session.where()));
        const QJsonObject entry = folder->entries.value(device.name);
        const MachineVerbs& verbs = *CommandRegistry::instance().machineVerbs(device.family);
        const bool accepted = replacements.contains(device.name);
        QStringList words = verbs.*verb;
        if (accepted && verb == &MachineVerbs::restore) words << verbs.replacement;
        outcomes[size_t(i)] = runChecked(
            session, device, entry, accepted, words,
            QDir(dir).filePath(entry.value(QStringLiteral("file")).toString()), nothing, says);
    });
    QStringList summary;
    QList<int> codes;
    for (const DeviceOutcome& outcome : outcomes) {
        if (outcome.line.isEmpty()) continue;  // not asked for (--only)
        summary << outcome.line;
        codes << outcome.code;
    }
    printOut(QStringLiteral("%1:\n%2\n").arg(folder->setup.machine.machine, summary.join('\n')));
    return exitFor(codes);
}

}  // namespace

int runMachineVerify(const QString& dir, const QStringList& replacements) {
    return forEachSaved(
        dir, {}, replacements, &MachineVerbs::verify, QStringLiteral("It was not verified"),
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

int runMachineRestore(const QString& dir, const QStringList& only,
                      const QStringList& replacements) {
    return forEachSaved(
        dir, only, replacements, &MachineVerbs::restore,
        QStringLiteral("Nothing was written to it"),
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
