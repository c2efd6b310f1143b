// The CamCon's entries of the File menu: its project file (the family's
// file kind), the recent projects and the commissioning report.

#include "cam_page.h"
#include "camcon_window.h"

#include "commissioning_report.h"
#include "incoming_values.h"
#include "new_project_dialog.h"
#include "project_io.h"
#include "timing_bar.h"
#include "workspace.h"

#include "ui/camcon/cameditor/cam_document.h"
#include "ui/camcon/cameditor/cam_editor_widget.h"
#include "ui/device_session.h"
#include "ui/gui_settings.h"
#include "ui/main_window.h"
#include "ui/report_dialog.h"

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMenu>
#include <QMessageBox>

namespace cambench {

void CamConWindow::addFileEntries(QMenu* file) {
    file->addAction(tr("&New project…"), this, &CamConWindow::newProject);
    file->addAction(tr("&Open project…"), QKeySequence::Open, this, &CamConWindow::openProject);
    m_recentMenu = file->addMenu(tr("Recent &files"));
    connect(m_recentMenu, &QMenu::aboutToShow, this, &CamConWindow::fillRecentFiles);
    fillRecentFiles();
    file->addAction(tr("&Save project"), QKeySequence::Save, this, &CamConWindow::saveProject);
    file->addAction(tr("Save project &as…"), QKeySequence::SaveAs, this,
                    &CamConWindow::saveProjectAs);
    file->addSeparator();
    file->addAction(tr("Commissioning &report (PDF)…"), this,
                    &CamConWindow::exportReportInteractive);
}

void CamConWindow::newProject() {
    NewProjectDialog dialog(m_workspace->info(), window());
    if (dialog.exec() != QDialog::Accepted) return;
    if (m_workspace->changedCount() > 0 &&
        QMessageBox::question(window(), tr("New project"),
                              tr("%n change(s) are not written or saved. Discard them for a new, "
                                 "empty project?",
                                 nullptr, m_workspace->changedCount())) != QMessageBox::Yes)
        return;
    gui()->session()->disconnectFromDevice();
    m_workspace->clear(emptyProject(dialog.capacities()).device);
    m_workspace->setProjectPath({});
    showSection(Cams);
}

void CamConWindow::openProject() {
    const QString path = QFileDialog::getOpenFileName(window(), tr("Open project"), QString(),
                                                      tr("CamBench projects (*.json)"));
    if (!path.isEmpty()) openProjectFile(path);
}

void CamConWindow::openProjectFile(const QString& path) {
    const Result<Project> project = loadProject(path);
    if (!project) {
        ReportDialog::present(window(), QMessageBox::Warning, tr("Open project"),
                              tr("The project %1 was not opened.").arg(path),
                              project.error().message);
        if (!QFileInfo::exists(path)) guisettings::removeRecentProject(path);
        return;
    }
    if (!takeIncoming(window(), *m_workspace, project.value(), ValueSource::File)) {
        showMessage(tr("Project %1 not opened: your edits are unchanged.").arg(path));
        return;
    }
    // The editors follow the project's device; writing checks the device on the line.
    if (!(m_workspace->info() == project->device)) m_workspace->setInfo(project->device, false);
    m_workspace->setProjectPath(path);
    guisettings::addRecentProject(path);
    showMessage(
        tr("Project %1 opened. Its content is not on the device until you write it.").arg(path));
}

void CamConWindow::fillRecentFiles() {
    m_recentMenu->clear();
    const QStringList recent = guisettings::recentProjects();
    for (int i = 0; i < recent.size(); ++i) {
        const QString path = recent.at(i);
        // "&1 name.json" – the path in the tooltip and the status bar.
        QString name = QFileInfo(path).fileName();
        QAction* action = m_recentMenu->addAction(QStringLiteral("&%1 %2").arg(i + 1).arg(
            name.replace(QLatin1Char('&'), QLatin1String("&&"))));
        action->setToolTip(path);
        action->setStatusTip(path);
        connect(action, &QAction::triggered, this, [this, path] { openProjectFile(path); });
    }
    if (recent.isEmpty()) m_recentMenu->addAction(tr("No recent projects"))->setEnabled(false);
    m_recentMenu->addSeparator();
    QAction* clear = m_recentMenu->addAction(tr("&Clear list"), this, [] {
        for (const QString& path : guisettings::recentProjects())
            guisettings::removeRecentProject(path);
    });
    clear->setEnabled(!recent.isEmpty());
}

void CamConWindow::saveProject() {
    if (m_workspace->projectPath().isEmpty()) {
        saveProjectAs();
    } else {
        saveProjectTo(m_workspace->projectPath());
    }
}

void CamConWindow::saveProjectAs() {
    const QString path = QFileDialog::getSaveFileName(
        window(), tr("Save project"), m_workspace->projectPath(), tr("CamBench projects (*.json)"));
    if (!path.isEmpty()) saveProjectTo(path);
}

Status CamConWindow::saveProjectTo(const QString& path) {
    if (isReadingDevice()) {
        // Half a device in a file would look like a whole one later.
        const Status refused =
            Error::usage(tr("The device is still being read; the project was not "
                            "saved. Save again when the reading is done."));
        ReportDialog::present(window(), QMessageBox::Information, tr("Save project"),
                              refused.error().message);
        return refused;
    }
    const Project project = projectFromWorkspace(*m_workspace);
    const Status saved = cambench::saveProject(path, project);
    if (!saved) {
        ReportDialog::present(window(), QMessageBox::Warning, tr("Save project"),
                              tr("The project was not saved."), saved.error().message);
        return saved;
    }
    m_workspace->setProjectPath(path);
    guisettings::addRecentProject(path);
    // Values as the device holds them are saved as they are; say which a
    // write would refuse.
    const QStringList warnings = validateProject(project);
    showMessage(warnings.isEmpty()
                    ? tr("Project saved to %1.").arg(path)
                    : tr("Project saved to %1. %n value(s) are outside what a write accepts (%2).",
                         nullptr, int(warnings.size()))
                          .arg(path, warnings.first()));
    return saved;
}

Status CamConWindow::exportReport(const QString& path, std::optional<double> timingSpeed) {
    return CommissioningReport::write(path, *m_workspace, {timingSpeed, {}});
}

void CamConWindow::exportReportInteractive() {
    // The timing tables at a speed the user gives: the cam page's when its
    // timing view is on; 0 leaves them out.
    const TimingBar* timing = m_cams->timingBar();
    bool ok = false;
    const double speed =
        QInputDialog::getDouble(window(), tr("Commissioning report"),
                                tr("Timing tables at the speed (%1); 0 leaves them out:")
                                    .arg(speedUnit(m_workspace->cams()->axis())),
                                timing->timingShown() ? timing->speed() : 0.0, 0, 1e7, 1, &ok);
    if (!ok) return;
    const QString path = QFileDialog::getSaveFileName(window(), tr("Commissioning report"),
                                                      QString(), tr("PDF files (*.pdf)"));
    if (path.isEmpty()) return;
    const Status written =
        exportReport(path, speed > 0 ? std::optional<double>(speed) : std::nullopt);
    if (!written) {
        QMessageBox::warning(window(), tr("Commissioning report"), written.error().message);
    } else {
        showMessage(tr("Report written to %1.").arg(path));
    }
}

}  // namespace cambench
