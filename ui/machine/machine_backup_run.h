#pragma once

#include "comm/usecases/machine_backup.h"
#include "model/machine/machine_backup_folder.h"
#include "ui/machine/machine_progress.h"

#include <QHash>
#include <QObject>
#include <QPointer>
#include <QStringList>

class QWidget;

namespace cambench {

class Machine;
class MachineUnit;

// Machine → Back up…, Verify…, Restore… (issue 36, item 4): each device
// through the machine's use cases (comm/usecases/machine_backup.h: who
// answers first - another device than the one recorded is said and nothing
// is saved from it, verified or written to it - then its family's typed
// backup part), each on its own worker, all at once, with a bar and a
// result line per device and the machine's STOP (MachineProgress). The
// folder is the command line's (model/machine/machine_backup_folder.h):
// machine.json, one file per device, manifest.json rewritten after each
// device. A restore asks each device's identity first (askRestoreTarget),
// reads and lists every device's plan, asks once, then writes; its safety
// copies go to a folder beside the backup's.
class MachineBackupRun : public QObject {
    Q_OBJECT
public:
    // `note`: why (the manifest's note, as the command line's -m).
    static MachineBackupRun* backUp(Machine* machine, const QString& dir, const QString& note,
                                    QWidget* parent);
    static MachineBackupRun* verify(Machine* machine, const QString& dir, QWidget* parent);
    static MachineBackupRun* restore(Machine* machine, const QString& dir, QWidget* parent);

    MachineProgress* progress() const { return m_progress; }
    // What was found, device by device, in full: the differences of a
    // verify, the plans and the outcome of each item of a restore.
    QString details() const { return m_details.join(QLatin1Char('\n')); }
    // The restore's safety copies (empty when none was taken).
    QString safetyFolder() const { return m_safetyDir; }
    bool isDone() const { return m_done; }

Q_SIGNALS:
    // Every device is done (for a restore declined: nothing was written).
    void finished();

private:
    MachineBackupRun(Machine* machine, const QString& dir, const QString& title, QWidget* parent);
    void startBackup(const QString& note);
    // The folder's manifest into m_manifest; false (every line says why,
    // the run ended) when it cannot be read.
    bool readFolder();
    void startVerify();
    void askIdentities(QList<MachineUnit*> left);
    void planAll();
    void confirmAndRestore();
    void restoreAll();
    // A restore's safety copy of `unit` kept for the safety folder's manifest.
    void keepSafetyCopy(const MachineUnit* unit, const usecases::DeviceRestored& restored);
    void listCopiesAndFinish();
    void deviceSaved(MachineUnit* unit, const ManifestEntry& entry);
    // Every device is done: finished(), queued.
    void end();
    void note(const QString& line) { m_details << line; }
    // `unit`'s result line (in the details, too).
    void finishRow(const MachineUnit* unit, bool ok, const QString& line);
    // Where the questions are asked: the dialog, or the window once it was closed.
    QWidget* asker() const;
    // The saved entry of `unit` in the folder's manifest, or why there is none.
    const ManifestEntry* entryOf(const MachineUnit* unit, QString* why) const;

    Machine* m_machine;
    QString m_dir;
    QPointer<QWidget> m_parent;
    QPointer<MachineProgress> m_progress;  // closed by the person: the run goes on
    MachineManifest m_manifest;    // the folder's (verify, restore) or the one being written
    QList<ManifestEntry> m_saved;  // a backup's entries so far, in the file's order
    QStringList m_details;
    // A restore: the person's word per device, what each plan will write.
    QHash<QString, ManifestEntry> m_entries;  // what each device's restore writes
    QHash<QString, ReplacementConsent> m_consents;
    QHash<QString, QString> m_plans;
    QList<MachineUnit*> m_restoring;
    QString m_safetyDir;
    QList<ManifestEntry> m_copies;  // the restore's safety copies so far
    int m_left = 0;
    bool m_done = false;
};

}  // namespace cambench
