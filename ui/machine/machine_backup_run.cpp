#include "machine_backup_run.h"

#include "machine.h"
#include "machine_progress.h"
#include "machine_unit.h"

#include "comm/usecases/machine_backup.h"
#include "model/atomic_file.h"
#include "model/file_read.h"
#include "ui/device_session.h"
#include "ui/replacement_question.h"
#include "ui/report_dialog.h"
#include "ui/sentence.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>

namespace cambench {

namespace {

// At most this many differences on a device's result line; all of them in
// the details.
constexpr int kLinesShown = 5;

QString shortList(const QStringList& lines) {
    QStringList shown = lines.mid(0, kLinesShown);
    if (lines.size() > kLinesShown)
        shown << MachineBackupRun::tr("… and %n more (Details)", nullptr,
                                      int(lines.size()) - kLinesShown);
    return shown.join(QLatin1Char('\n'));
}

QStringList differenceLines(const QList<BackupDifference>& differences) {
    QStringList lines;
    for (const BackupDifference& difference : differences) lines << difference.line();
    return lines;
}

// The revision app/gui/main.cpp names in the application's version
// ("0.9.0 (revision a7d0047)"): this library is built without the
// generated header, which changes with every commit. Empty when not named.
QString revisionOfThisBuild() {
    static const QRegularExpression named(QStringLiteral("\\(revision ([^)]+)\\)"));
    return named.match(QCoreApplication::applicationVersion()).captured(1);
}

// Who does it now, why, and with which build: the manifest's author.
BackupAuthor thisPerson(const QString& note) {
    return {loginName(), note, QStringLiteral(CAMBENCH_VERSION), revisionOfThisBuild()};
}

Result<MachineManifest> readManifest(const QString& dir) {
    const QString path = QDir(dir).filePath(kMachineManifestFile);
    const Result<QByteArray> bytes = readFileBytes(path);
    if (!bytes)
        return Error::invalidData(MachineBackupRun::tr("%1 is not a machine backup folder: %2")
                                      .arg(dir, bytes.error().message));
    return parseManifest(*bytes, path);
}

}  // namespace

MachineBackupRun::MachineBackupRun(Machine* machine, const QString& dir, const QString& title,
                                   QWidget* parent)
    : QObject(parent),
      m_machine(machine),
      m_dir(dir),
      m_parent(parent),
      m_progress(new MachineProgress(title, machine->units(), parent)) {
    m_progress->setAttribute(Qt::WA_DeleteOnClose);
    m_progress->show();
}

void MachineBackupRun::end() {
    // Queued: a run that ends at once (no backup folder) still reaches
    // whoever connects to finished() after it was made.
    QMetaObject::invokeMethod(
        this,
        [this] {
            m_done = true;
            Q_EMIT finished();
        },
        Qt::QueuedConnection);
}

QWidget* MachineBackupRun::asker() const {
    if (m_progress) return m_progress;
    return m_parent;
}

void MachineBackupRun::finishRow(const MachineUnit* unit, bool ok, const QString& line) {
    // Every line also in the details: the dialog may have been closed.
    note(QStringLiteral("%1: %2").arg(unit->name(), line));
    if (m_progress) m_progress->finish(unit, ok, line);
}

const ManifestEntry* MachineBackupRun::entryOf(const MachineUnit* unit, QString* why) const {
    const ManifestEntry* entry = m_manifest.entry(unit->name());
    if (!entry) {
        *why = tr("not in this backup");
        return nullptr;
    }
    if (!entry->saved()) {
        *why = tr("not saved in this backup (%1)").arg(entry->result);
        return nullptr;
    }
    if (!stillSaved(*entry, m_dir)) {
        *why = tr("its file in the backup changed since it was saved");
        return nullptr;
    }
    return entry;
}

// ---- Back up ---------------------------------------------------------------

MachineBackupRun* MachineBackupRun::backUp(Machine* machine, const QString& dir,
                                           const QString& note, QWidget* parent) {
    auto* run = new MachineBackupRun(machine, dir, tr("Back up the machine"), parent);
    run->startBackup(note);
    return run;
}

void MachineBackupRun::startBackup(const QString& note) {
    m_manifest = MachineManifest{};
    m_manifest.machine = m_machine->name();
    m_manifest.author = thisPerson(note);
    m_manifest.started = QDateTime::currentDateTimeUtc();
    // The machine file first: an interrupted backup still holds it.
    const Status made =
        QDir().mkpath(m_dir)
            ? writeFileAtomically(QDir(m_dir).filePath(kMachineBackupFile),
                                  machineFileJson(m_machine->file()))
            : Status(Error::communication(
                  tr("cannot make the folder %1; check the path and its rights").arg(m_dir)));
    m_left = int(m_machine->units().size());
    for (MachineUnit* unit : m_machine->units()) {
        if (!made) {
            finishRow(unit, false, tr("not saved: %1").arg(made.error().message));
            continue;
        }
        const MachineDevice device = unit->device();
        const QString dir = m_dir;
        // A Result: a job a Cancel or a STOP drops unrun still answers.
        unit->session()->worker().run<Result<usecases::DeviceBackedUp>>(
            this, comm::JobPriority::User, tr("Back up %1").arg(unit->name()),
            [device, dir](comm::JobContext& job) -> Result<usecases::DeviceBackedUp> {
                return usecases::backUpMachineDevice(job, device, dir, false);
            },
            [this, unit](Result<usecases::DeviceBackedUp> done) {
                ManifestEntry entry;
                if (done) {
                    entry = done->entry;
                    if (done->checked && !done->checked->another.isEmpty())
                        entry.result = tr("failed: %1 - nothing was saved from it")
                                           .arg(done->checked->another);
                } else {
                    entry.name = unit->name();
                    entry.family = unit->device().family;
                    entry.file = deviceFileName(unit->name());
                    entry.result = tr("failed: %1").arg(done.error().message);
                }
                deviceSaved(unit, entry);
            });
    }
    if (!made) end();
}

void MachineBackupRun::deviceSaved(MachineUnit* unit, const ManifestEntry& entry) {
    m_saved << entry;
    // The manifest after each device, in the machine file's order: an
    // interrupted backup says what it has.
    m_manifest.devices.clear();
    for (const MachineUnit* each : m_machine->units())
        for (const ManifestEntry& saved : m_saved)
            if (saved.name == each->name()) m_manifest.devices << saved;
    const Status written =
        writeFileAtomically(QDir(m_dir).filePath(kMachineManifestFile), manifestJson(m_manifest));
    // Saved with items left out is not "saved" alone: each item is named.
    const bool ok = entry.saved() && entry.incomplete.isEmpty() && written.ok();
    QString line = entry.saved() ? tr("saved: %1").arg(entry.summary) : entry.result;
    if (entry.saved() && !entry.incomplete.isEmpty())
        line += QLatin1Char('\n') +
                tr("NOT SAVED: %1").arg(entry.incomplete.join(QStringLiteral("; ")));
    if (!written) line += QLatin1Char(' ') + tr("(the manifest: %1)").arg(written.error().message);
    finishRow(unit, ok, line);
    if (--m_left > 0) return;
    // The machine file with the identity each saved device answered with.
    MachineFile file = m_machine->file();
    for (MachineDevice& device : file.devices)
        if (const ManifestEntry* saved = m_manifest.entry(device.name); saved && saved->saved())
            device.identity = saved->identity;
    if (const Status saved =
            writeFileAtomically(QDir(m_dir).filePath(kMachineBackupFile), machineFileJson(file));
        !saved)
        note(tr("The machine file in %1 lacks the identities: %2")
                 .arg(m_dir, saved.error().message));
    end();
}

// ---- Verify ----------------------------------------------------------------

MachineBackupRun* MachineBackupRun::verify(Machine* machine, const QString& dir, QWidget* parent) {
    auto* run = new MachineBackupRun(machine, dir, tr("Verify the machine"), parent);
    if (run->readFolder()) run->startVerify();
    return run;
}

bool MachineBackupRun::readFolder() {
    const Result<MachineManifest> manifest = readManifest(m_dir);
    if (!manifest) {
        for (MachineUnit* unit : m_machine->units())
            finishRow(unit, false, manifest.error().message);
        end();
        return false;
    }
    m_manifest = *manifest;
    return true;
}

void MachineBackupRun::startVerify() {
    m_left = int(m_machine->units().size());
    const auto done = [this](MachineUnit* unit, bool ok, const QString& line) {
        finishRow(unit, ok, line);
        if (--m_left == 0) end();
    };
    for (MachineUnit* unit : m_machine->units()) {
        QString why;
        const ManifestEntry* found = entryOf(unit, &why);
        if (!found) {
            done(unit, false, tr("not verified: %1").arg(why));
            continue;
        }
        const ManifestEntry entry = *found;
        const QString dir = m_dir;
        unit->session()->worker().run<Result<usecases::DeviceVerified>>(
            this, comm::JobPriority::User, tr("Verify %1").arg(unit->name()),
            [entry, dir](comm::JobContext& job) {
                return usecases::verifyMachineDevice(job, entry, dir, {});
            },
            [this, unit, done](Result<usecases::DeviceVerified> verified) {
                if (!verified) {
                    done(unit, false, tr("not verified: %1").arg(verified.error().message));
                    return;
                }
                if (!verified->checked.another.isEmpty()) {
                    done(unit, false, tr("%1 - not verified").arg(verified->checked.another));
                    return;
                }
                const usecases::BackupComparison& comparison = verified->comparison;
                const QStringList lines = differenceLines(comparison.differences);
                m_details << lines << comparison.notes;
                if (comparison.equal()) {
                    done(unit, true,
                         tr("equal: %n item(s) compared", nullptr, comparison.compared));
                    return;
                }
                done(unit, false,
                     tr("%n difference(s):", nullptr, int(lines.size())) + QLatin1Char('\n') +
                         shortList(lines));
            });
    }
}

// ---- Restore ---------------------------------------------------------------

MachineBackupRun* MachineBackupRun::restore(Machine* machine, const QString& dir, QWidget* parent) {
    auto* run = new MachineBackupRun(machine, dir, tr("Restore the machine"), parent);
    if (!run->readFolder()) return run;
    QList<MachineUnit*> asked;
    for (MachineUnit* unit : machine->units()) {
        QString why;
        // Taken once: each step of this restore writes what was checked here.
        if (const ManifestEntry* entry = run->entryOf(unit, &why)) {
            run->m_entries.insert(unit->name(), *entry);
            asked << unit;
        } else
            run->finishRow(unit, false, tr("not restored: %1").arg(why));
    }
    run->askIdentities(asked);
    return run;
}

void MachineBackupRun::askIdentities(QList<MachineUnit*> left) {
    // One device's question at a time: each names its device.
    if (left.isEmpty()) {
        planAll();
        return;
    }
    MachineUnit* unit = left.takeFirst();
    const QString name = tr("the backup of %1").arg(unit->name());
    askRestoreTarget(
        unit->session(), this, asker(), tr("Restore %1").arg(unit->name()), name,
        m_entries.value(unit->name()).identity,
        [this, unit, left](const ReplacementConsent& consent) {
            m_consents.insert(unit->name(), consent);
            askIdentities(left);
        },
        [this, unit, left](const QString& declined) {
            finishRow(unit, false, tr("not restored: %1").arg(declined));
            askIdentities(left);
        });
}

void MachineBackupRun::planAll() {
    m_left = 0;
    for (MachineUnit* unit : m_machine->units())
        if (m_consents.contains(unit->name())) ++m_left;
    if (m_left == 0) {
        end();
        return;
    }
    for (MachineUnit* unit : m_machine->units()) {
        if (!m_consents.contains(unit->name())) continue;
        const ManifestEntry entry = m_entries.value(unit->name());
        usecases::RestoreRequest request;
        request.replacement = m_consents.value(unit->name());
        const QString dir = m_dir;
        unit->session()->worker().run<Result<usecases::DevicePlanned>>(
            this, comm::JobPriority::User, tr("Plan the restore of %1").arg(unit->name()),
            [entry, dir, request](comm::JobContext& job) {
                return usecases::planMachineDevice(job, entry, dir, request);
            },
            [this, unit](Result<usecases::DevicePlanned> planned) {
                QString line;
                if (!planned) {
                    line = tr("not restored: %1").arg(planned.error().message);
                } else if (!planned->checked.another.isEmpty()) {
                    line = tr("not restored: %1").arg(planned->checked.another);
                } else {
                    QStringList plan = planned->plan.steps;
                    plan << differenceLines(planned->plan.changes);
                    m_plans.insert(
                        unit->name(),
                        tr("%1: %n item(s) to change", nullptr, int(planned->plan.changes.size()))
                                .arg(unit->name()) +
                            QLatin1Char('\n') + plan.join(QLatin1Char('\n')));
                    m_restoring << unit;
                    line = tr("plan read: %n item(s) to change", nullptr,
                              int(planned->plan.changes.size()));
                }
                finishRow(unit, planned && planned->checked.another.isEmpty(), line);
                if (--m_left == 0) confirmAndRestore();
            });
    }
}

void MachineBackupRun::confirmAndRestore() {
    if (m_restoring.isEmpty()) {
        end();
        return;
    }
    QStringList plans;
    QStringList names;
    for (const MachineUnit* unit : m_restoring) {
        plans << m_plans.value(unit->name());
        names << unit->name();
    }
    m_details << plans;
    // Every plan before the first byte; one question for all.
    QMessageBox ask(QMessageBox::Warning, tr("Restore the machine"),
                    tr("Restore %1 from %2?").arg(names.join(QStringLiteral(", ")), m_dir),
                    QMessageBox::Cancel, asker());
    ask.setObjectName(QStringLiteral("machineRestoreQuestion"));
    ask.setInformativeText(
        tr("What each device holds is saved beside the backup folder first. "
           "Then this is written:"));
    ask.setDetailedText(plans.join(QStringLiteral("\n\n")));
    QPushButton* yes = ask.addButton(tr("Restore"), QMessageBox::DestructiveRole);
    ask.setDefaultButton(QMessageBox::Cancel);
    ask.exec();
    if (ask.clickedButton() != yes) {
        for (const MachineUnit* unit : m_restoring) {
            if (m_progress) m_progress->restart(unit);  // its line said "plan read"
            finishRow(unit, false, tr("not restored: cancelled, nothing was written"));
        }
        m_restoring.clear();
        end();
        return;
    }
    restoreAll();
}

void MachineBackupRun::restoreAll() {
    m_safetyDir = safetyFolderPath(m_dir, QDateTime::currentDateTimeUtc());
    const bool made = QDir().mkpath(m_safetyDir);
    m_left = int(m_restoring.size());
    for (MachineUnit* unit : m_restoring) {
        if (m_progress) m_progress->restart(unit);
        if (!made) {
            finishRow(unit, false,
                      tr("not restored: cannot make the folder %1 for the safety "
                         "copies; nothing was written")
                          .arg(m_safetyDir));
            if (--m_left == 0) end();
            continue;
        }
        const ManifestEntry entry = m_entries.value(unit->name());
        usecases::RestoreRequest request;
        request.replacement = m_consents.value(unit->name());
        request.safetyCopy = QDir(m_safetyDir).filePath(entry.file);
        const QString dir = m_dir;
        unit->session()->worker().run<Result<usecases::DeviceRestored>>(
            this, comm::JobPriority::User, tr("Restore %1").arg(unit->name()),
            [entry, dir, request](comm::JobContext& job) {
                return usecases::restoreMachineDevice(job, entry, dir, request);
            },
            [this, unit](Result<usecases::DeviceRestored> restored) {
                QString line;
                bool ok = false;
                if (!restored) {
                    line = tr("not restored: %1").arg(restored.error().message);
                } else if (!restored->checked.another.isEmpty()) {
                    line = tr("not restored: %1").arg(restored->checked.another);
                } else {
                    const usecases::OutcomeTally& outcomes = restored->result.outcomes;
                    ok = outcomes.complete();
                    line = (ok ? tr("restored: %1") : tr("NOT RESTORED completely: %1"))
                               .arg(outcomes.summary());
                    for (const usecases::OutcomeLine& item : outcomes.lines())
                        m_details << QStringLiteral("%1: %2").arg(unit->name(), item.text);
                    keepSafetyCopy(unit, *restored);
                }
                finishRow(unit, ok, line);
                if (--m_left == 0) listCopiesAndFinish();
            });
    }
}

void MachineBackupRun::keepSafetyCopy(const MachineUnit* unit,
                                      const usecases::DeviceRestored& restored) {
    const QString copy = restored.result.safetyCopy;
    if (copy.isEmpty()) return;
    const ManifestEntry entry = m_entries.value(unit->name());
    sameModeAs(copy, QDir(m_dir).filePath(entry.file));
    m_copies << safetyCopyEntry(entry, copy, restored.checked.found.identity,
                                restored.checked.found.text);
}

void MachineBackupRun::listCopiesAndFinish() {
    // In the machine file's order, as a backup lists its devices.
    QList<ManifestEntry> copies;
    for (const MachineUnit* unit : m_machine->units())
        for (const ManifestEntry& copy : m_copies)
            if (copy.name == unit->name()) copies << copy;
    const Status listed =
        listSafetyCopies(m_dir, m_safetyDir, m_machine->file(),
                         thisPerson(tr("safety copies of a restore from %1").arg(m_dir)), copies);
    if (copies.isEmpty()) m_safetyDir.clear();
    if (!listed)
        note(tr("The safety copies in %1 are not listed: %2")
                 .arg(m_safetyDir, listed.error().message));
    else if (!copies.isEmpty())
        note(tr("What the devices held before: %1").arg(m_safetyDir));
    end();
}

}  // namespace cambench
