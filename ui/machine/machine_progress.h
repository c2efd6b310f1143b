#pragma once

#include <QDialog>
#include <QHash>
#include <QList>

class QDialogButtonBox;
class QLabel;
class QProgressBar;

namespace cambench {

class MachineUnit;

// What a machine-wide run (the report's reads, backup, verify, restore)
// shows while it runs: one row per device - its name, a bar fed by its own
// worker's progress, and its result line once it is done; the program's
// STOP above them (DialogStop) and on Escape, as in every dialog. Devices on
// different ports run at once, each on its own worker, so each has its own
// bar. Cancel cancels what every device is doing; Close once all are done.
class MachineProgress : public QDialog {
    Q_OBJECT
public:
    MachineProgress(const QString& title, const QList<MachineUnit*>& units,
                    QWidget* parent = nullptr);

    // `unit` is done: its bar full (or stopped) and its line said.
    void finish(const MachineUnit* unit, bool ok, const QString& line);
    // `unit` runs again (the next step of a run: a restore after its plan).
    void restart(const MachineUnit* unit);
    bool allFinished() const;
    // The result line of the device named `name` (empty while it runs).
    QString resultLine(const QString& name) const;
    QList<QString> names() const;
    QProgressBar* bar(const QString& name) const;
    bool cancelled() const { return m_cancelled; }

Q_SIGNALS:
    // Every device is done.
    void finished();

private:
    struct Row {
        const MachineUnit* unit = nullptr;
        QProgressBar* bar = nullptr;
        QLabel* line = nullptr;
        bool done = false;
    };
    Row* rowOf(const QString& name);
    const Row* rowOf(const QString& name) const;
    void cancelAll();

    QList<Row> m_rows;
    QDialogButtonBox* m_buttons;
    bool m_cancelled = false;
};

}  // namespace cambench
