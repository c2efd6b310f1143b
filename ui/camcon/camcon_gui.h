#pragma once

#include "ui/family_gui.h"

namespace cambench {

class CamConWindow;
class Shell;
class Workspace;

// The CamCon's part of the GUI for the whole run: the workspace of edits
// (what is on the PC, what the device holds, what is not written yet).
class CamConGui : public FamilyGui {
    Q_OBJECT
public:
    CamConGui(DeviceSession* session, QObject* parent = nullptr);

    Workspace* workspace() const { return m_workspace; }

    FamilyWindow* createWindow(MainWindow* window) override;
    QString identityLine() const override;
    QString windowSubject() const override;
    int unwrittenCount() const override;
    // Everything the device holds, every program too (Read everything).
    void readForReport(QWidget* parent, std::function<void(const Status&)> done) override;
    QString reportSection(QTextDocument& document, const QString& resourcePrefix) const override;
    // The programs whose cams differ, drawn one over the other (BackupProgramsView).
    QWidget* backupDrawing(const BackupSide& older, const BackupSide& newer) const override;

private:
    Workspace* m_workspace;
};

// The CamCon's workspace and part of the window of `shell` (the tests' and
// the screenshot tour's way in).
Workspace* camConWorkspace(const Shell& shell);
CamConWindow* camConWindow(const MainWindow* window);

}  // namespace cambench
