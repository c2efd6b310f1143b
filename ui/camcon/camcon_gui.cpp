#include "camcon_gui.h"

#include "backup_programs_view.h"
#include "camcon_window.h"
#include "commissioning_report.h"
#include "device_reads.h"
#include "workspace.h"

#include "model/camcon/camcon_family_id.h"
#include "ui/main_window.h"
#include "ui/shell.h"

#include <QFileInfo>

namespace cambench {

CamConGui::CamConGui(DeviceSession* session, QObject* parent)
    : FamilyGui(camconFamilyId, session, parent), m_workspace(new Workspace(this)) {
    connect(m_workspace, &Workspace::infoChanged, this, &FamilyGui::identityChanged);
    connect(m_workspace, &Workspace::otherDeviceNoteChanged, this, &FamilyGui::identityChanged);
    connect(m_workspace, &Workspace::changedCountChanged, this, &FamilyGui::titleChanged);
    connect(m_workspace, &Workspace::infoChanged, this, &FamilyGui::titleChanged);
    connect(m_workspace, &Workspace::projectPathChanged, this, &FamilyGui::titleChanged);
}

FamilyWindow* CamConGui::createWindow(MainWindow* window) {
    return new CamConWindow(this, window);
}

QString CamConGui::identityLine() const {
    if (!m_workspace->infoFromDevice()) return {};
    const DeviceInfo& info = m_workspace->info();
    QString line = tr("CamCon %1, device number %2.").arg(info.epromDate).arg(info.deviceNumber);
    if (!m_workspace->otherDeviceNote().isEmpty())
        line += QLatin1Char('\n') + m_workspace->otherDeviceNote();
    return line;
}

QString CamConGui::windowSubject() const {
    const QString projectPath = m_workspace->projectPath();
    if (!projectPath.isEmpty()) return QFileInfo(projectPath).fileName();
    return m_workspace->infoFromDevice() ? tr("CamCon %1 (device %2)")
                                               .arg(m_workspace->info().epromDate)
                                               .arg(m_workspace->info().deviceNumber)
                                         : tr("offline project");
}

int CamConGui::unwrittenCount() const {
    return m_workspace->changedCount();
}

void CamConGui::readForReport(QWidget* parent, std::function<void(const Status&)> done) {
    // Edits on this PC that a read would replace are asked about first.
    devicereads::readEverything(
        parent, session(), m_workspace, [done](const Status& status, const QStringList& skipped) {
            Q_UNUSED(skipped);  // the report says "not read" where a part is missing
            done(status);
        });
}

QString CamConGui::reportSection(QTextDocument& document, const QString& resourcePrefix) const {
    // The commissioning report, whole: what was read, when, and what is not written.
    CommissioningReport::Options options;
    options.resourcePrefix = resourcePrefix;
    return CommissioningReport::html(document, *m_workspace, options);
}

QWidget* CamConGui::backupDrawing(const BackupSide& older, const BackupSide& newer) const {
    return BackupProgramsView::create(older.path, older.label, newer.path, newer.label);
}

Workspace* camConWorkspace(const Shell& shell) {
    auto* camcon = qobject_cast<CamConGui*>(shell.family(camconFamilyId));
    return camcon ? camcon->workspace() : nullptr;
}

CamConWindow* camConWindow(const MainWindow* window) {
    return window ? qobject_cast<CamConWindow*>(window->familyWindow(camconFamilyId)) : nullptr;
}

}  // namespace cambench
