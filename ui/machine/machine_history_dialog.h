#pragma once

// Machine → History… (issue 37): the versions of the machine's archive
// (model/machine/machine_archive.h) with who, when, why and what changed
// in each; two versions - or one and the devices now - compared device by
// device in each family's terms (a table: device, item, before, after;
// where the family draws its backups, a drawing too);
// Restore this version (each device's identity checked and the plan listed
// before anything is written); Mark as released. The comparisons are the
// use case's (comm/usecases/machine_history.h), as for `machine diff` and
// `machine watch`. Names no family.

#include "comm/usecases/machine_history.h"
#include "model/machine/machine_archive.h"

#include <QDialog>
#include <QList>
#include <QMap>
#include <QPointer>
#include <QString>

#include <memory>
#include <optional>

class QLabel;
class QPushButton;
class QTableWidget;
class QTreeWidget;

namespace cambench {

class Machine;
class MachineHistoryJobs;

class MachineHistoryDialog : public QDialog {
    Q_OBJECT
public:
    // The machine's archive at `archive` (refused with a message in the
    // dialog when it is none).
    MachineHistoryDialog(Machine* machine, const QString& archive, QWidget* parent = nullptr);
    ~MachineHistoryDialog() override;

    // The columns of the version list and of the differences.
    enum VersionColumn { Version, Time, Author, Note, Released };
    enum DifferenceColumn { Device, Item, Before, After, Difference };

    QTreeWidget* versionList() const { return m_versions; }
    QTableWidget* differenceTable() const { return m_differences; }
    QLabel* statusLabel() const { return m_status; }
    QPushButton* compareButton() const { return m_compare; }
    QPushButton* compareNowButton() const { return m_compareNow; }
    QPushButton* restoreButton() const { return m_restore; }
    QPushButton* releaseButton() const { return m_release; }
    QPushButton* drawButton() const { return m_draw; }

    // The drawing of device `name`'s changes between the two states
    // compared last - two versions, or a version and the devices now
    // (hidden until shown); nullptr when its family draws none or it did
    // not change.
    QDialog* drawingOf(const QString& name) const { return m_drawings.value(name); }
    // Shows the drawing of the device of the difference table's current row.
    void showDrawing();

    // The two selected versions compared (the older first).
    void compareSelected();
    // The selected version against every device now (each read on its own line).
    void compareWithDevicesNow();
    // The selected version marked as the released one.
    void markReleased();
    // Reads each device's plan, lists it and, when the person agrees,
    // restores the selected version.
    void restoreSelected();

Q_SIGNALS:
    // A comparison, a release or a restore finished (the status line says how).
    void finished();

private:
    void reload();
    void updateButtons();
    // The selected versions' ids, newest first.
    QStringList selectedIds() const;
    void showChanges(const usecases::MachineChanges& changes, const QString& heading);
    // The device of the difference table's current row.
    QString currentDevice() const;
    // A machine backup folder read and what the drawings call it
    // ("version 1a2b3c4d5e", "the devices now").
    struct State {
        usecases::MachineFolderRead folder;
        QString label;
    };
    // A drawing of each device that changed from `older` to `newer` whose
    // family draws one, and the status line says which.
    void makeDrawings(const usecases::MachineChanges& changes, const State& older,
                      const State& newer);
    void dropDrawings();
    // The selected version taken out for the devices' jobs; false (said) when it failed.
    bool takeOutSelected();
    void say(const QString& text);

    Machine* m_machine;
    std::optional<MachineArchive> m_archive;
    QList<ArchiveVersion> m_list;
    QTreeWidget* m_versions;
    QTableWidget* m_differences;
    QLabel* m_status;
    QPushButton* m_compare;
    QPushButton* m_compareNow;
    QPushButton* m_restore;
    QPushButton* m_release;
    QPushButton* m_draw;
    QMap<QString, QPointer<QDialog>> m_drawings;
    std::optional<usecases::VersionFolder> m_folder;  // while devices' jobs use it
    MachineHistoryJobs* m_jobs = nullptr;
};

// Machine → History…: asks for the machine's archive folder (starting
// beside the machine file) and shows its history; nothing when cancelled.
void openMachineHistory(Machine* machine, QWidget* parent);

}  // namespace cambench
