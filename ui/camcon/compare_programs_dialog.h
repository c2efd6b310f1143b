#pragma once

#include "model/camcon/cam_program.h"
#include "model/camcon/program_diff.h"
#include "model/result.h"

#include <QDateTime>
#include <QDialog>

#include <functional>
#include <optional>

class QCheckBox;
class QComboBox;
class QLabel;
class QListWidget;
class QPushButton;
class QSpinBox;

namespace cambench {

class DeviceSession;
class ProgramDiffView;
class Workspace;

// Tools → Compare programs…: any two of the edits on this PC, the device, a
// project file or a CSV cam file, each with its program, drawn one over the
// other (ProgramDiffView) with the list of differences beside; a row
// selects its cams in the diagram and a click in the diagram its row. The
// device side is read first, and the time it was read is shown.
class CompareProgramsDialog : public QDialog {
    Q_OBJECT
public:
    enum class Source { Edited, Device, ProjectFile, CsvFile };

    CompareProgramsDialog(DeviceSession* session, Workspace* workspace, QWidget* parent = nullptr);

    // For tests and scripts: what each side is. `path` for the files.
    void setSide(int side, Source source, int program, const QString& path = {});
    Source sideSource(int side) const;
    void compare();
    bool isReading() const { return m_reading > 0; }
    QStringList differenceTexts() const;
    ProgramDiffView* view() const { return m_view; }
    QListWidget* list() const { return m_list; }
    QString summary() const;
    // One line of the list, in the user's language.
    static QString differenceText(const CamDifference& difference);

    // Applying: every row has a check box; with the device on one side,
    // the checked differences are written to it (the device's program as
    // read, with them applied, through the one write path), after a
    // confirmation that names what is written. Then both sides are read
    // again, so the list shows what the device holds now.
    void setChecked(int row, bool checked);
    bool canApply() const;
    void applyChecked();
    QString lastApplyResult() const { return m_applyResult; }

Q_SIGNALS:
    void compared(bool ok);
    void applied(bool complete);

private:
    struct SideWidgets {
        QComboBox* source;
        QSpinBox* program;
        QPushButton* choose;
        QLabel* path;
        QString file;
    };
    struct Loaded {
        CamProgram program;
        QString label;
        bool fromDevice = false;
        QDateTime readAt;  // UTC, when read from the device
    };
    void buildSide(int side, QWidget* box);
    void updateSide(int side);
    // The program of side `side`, then `done` (at once, or after the read).
    void load(int side, std::function<void(Result<Loaded>)> done);
    void showComparison(const Loaded& a, const Loaded& b);
    void fail(const QString& message);
    void updateApply();
    QList<CamDifference> checkedDifferences() const;

    DeviceSession* m_session;
    Workspace* m_workspace;
    SideWidgets m_sides[2];
    QPushButton* m_compare;
    QPushButton* m_apply;
    QCheckBox* m_fold;
    QLabel* m_summary;
    ProgramDiffView* m_view;
    QListWidget* m_list;
    int m_reading = 0;
    int m_generation = 0;  // of the comparison running
    std::optional<Loaded> m_results[2];
    ProgramDiff m_diff;     // of the comparison shown
    int m_deviceSide = -1;  // the side read from the device in it, -1 none
    int m_applying = 0;
    QString m_applyResult;
    QString m_pendingNote;  // said with the next comparison (the write before it)
};

}  // namespace cambench
