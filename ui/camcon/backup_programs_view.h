#pragma once

// The CamCon's drawing of two of its backups (FamilyGui::backupDrawing,
// issue 37): each program whose cams (or name) differ between the two
// EEPROM images, one chosen at a time and drawn one over the other by the
// ProgramDiffView of Tools → Compare programs, with its differences listed
// beside in the same words. The machine's history shows it for a CamCon
// whose programs changed between two versions.

#include "model/camcon/cam_axis.h"
#include "model/camcon/project_file.h"

#include <QList>
#include <QString>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QListWidget;

namespace cambench {

class ProgramDiffView;

class BackupProgramsView : public QWidget {
    Q_OBJECT
public:
    // The programs of the backups at `olderPath` and `newerPath` that
    // differ; nullptr when the images cannot be decoded (a backup of the
    // older format holds no content) or no program differs.
    static BackupProgramsView* create(const QString& olderPath, const QString& olderLabel,
                                      const QString& newerPath, const QString& newerLabel);

    // The numbers of the programs that differ, ascending.
    QList<int> programs() const { return m_numbers; }
    // Draws program `number` (one of programs()).
    void showProgram(int number);
    int shownProgram() const;
    QComboBox* programChoice() const { return m_choice; }
    ProgramDiffView* view() const { return m_view; }
    QListWidget* differenceList() const { return m_list; }
    QString summary() const;

private:
    BackupProgramsView(Project older, QString olderLabel, Project newer, QString newerLabel);
    // Program `number` of `project`; an empty one with that number when it holds none.
    static CamProgram programOf(const Project& project, int number);
    void showChoice(int index);

    Project m_older;
    Project m_newer;
    QString m_olderLabel;
    QString m_newerLabel;
    Axis m_axis;
    QList<int> m_numbers;
    QComboBox* m_choice;
    QCheckBox* m_fold;
    QLabel* m_summary;
    ProgramDiffView* m_view;
    QListWidget* m_list;
};

}  // namespace cambench
