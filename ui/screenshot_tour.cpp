#include "screenshot_tour.h"

#include "connection_page.h"
#include "device_session.h"
#include "main_window.h"
#include "progress_page.h"
#include "shell.h"
#include "shell_log.h"
#include "ui/camcon/backup_wizard.h"
#include "ui/camcon/cam_page.h"
#include "ui/camcon/compare_dialog.h"
#include "ui/camcon/monitor_page.h"
#include "ui/camcon/plc_page.h"
#include "ui/camcon/settings_page.h"
#include "ui/camcon/terminal_page.h"
#include "ui/camcon/users_page.h"
#include "ui/camcon/workspace.h"

#include "ui/camcon/cameditor/cam_document.h"
#include "ui/camcon/cameditor/cam_editor_widget.h"

#include <QDir>
#include <QListWidget>
#include <QPainter>
#include <QTimer>

namespace cambench {

namespace {
const QSize kWindowSize(1280, 800);
constexpr int kStepTimeoutMs = 60000;
constexpr int kPollMs = 100;
}  // namespace

ScreenshotTour::ScreenshotTour(Shell* shell, const QString& directory, QObject* parent)
    : QObject(parent), m_shell(shell), m_directory(directory) {
    m_backupPath = QDir(directory).filePath(QStringLiteral("screenshot-backup.json"));
}

void ScreenshotTour::start() {
    QDir().mkpath(m_directory);
    m_shell->window()->resize(kWindowSize);
    buildSteps();
    runStep(0);
}

void ScreenshotTour::buildSteps() {
    MainWindow* w = m_shell->window();
    Workspace* ws = m_shell->workspace();
    const auto loaded = [ws] { return ws->infoFromDevice() && ws->cams()->hasDeviceCopy(0); };
    auto* devices = w->connectionPage()->findChild<QListWidget*>();
    m_steps = {
        {QStringLiteral("01-connection"),
         [w] {
             w->showSection(MainWindow::Connection);
             w->connectionPage()->scanBus();
         },
         [loaded, devices] { return loaded() && devices && devices->count() > 0; },
         {}},
        {QStringLiteral("02-cam-editor"), [w] { w->showSection(MainWindow::Cams); }, loaded, {}},
        {QStringLiteral("03-dead-times"),
         [w] { w->showSection(MainWindow::DeadTimes); },
         [ws] { return ws->outputSettingsKnown(); },
         {}},
        {QStringLiteral("04-settings"),
         [w] { w->showSection(MainWindow::Settings); },
         [ws] { return ws->settingsKnown(); },
         {}},
        {QStringLiteral("05-users"),
         [w] { w->showSection(MainWindow::Users); },
         [w, ws] {
             if (ws->users().isEmpty()) return false;
             w->usersPage()->selectUser(0);
             return true;
         },
         {}},
        {QStringLiteral("06-plc"),
         [w] {
             w->showSection(MainWindow::Plc);
             w->plcPage()->showNetwork(PlcNetwork::O, 0);
             w->plcPage()->readNetwork();
         },
         [ws] { return ws->devicePlcNetworks().contains(Workspace::plcKey(PlcNetwork::O, 0)); },
         {}},
        {QStringLiteral("07-monitor"),
         [w] { w->showSection(MainWindow::Monitor); },
         [w] { return w->monitorPage()->trendSamples() >= 48; },
         {}},
        {QStringLiteral("08-compare"),
         [this, w, ws] {
             // An edit to compare: one cam moved, one dead time changed.
             CamDocument* cams = ws->cams();
             const Track track = cams->track(0, 1);
             if (!track.cams.isEmpty()) {
                 Cam cam = track.cams.first();
                 cam.off = std::min<qint32>(cam.off + 10, ws->info().maxPosition);
                 cams->setCam(0, 1, 0, cam);
             }
             cams->setDeadTime(2, cams->deadTime(2) + 15);
             w->showSection(MainWindow::Cams);
             m_dialog = w->openCompare();
         },
         [this] {
             auto* compare = static_cast<CompareDialog*>(m_dialog);
             return !compare->isReading() && compare->differenceCount() > 0;
         },
         [this] { return m_dialog; }},
        {QStringLiteral("09-backup-wizard"),
         [this, w] {
             m_dialog->close();
             w->showSection(MainWindow::Backup);
             auto* wizard = w->openBackupWizard();
             m_dialog = wizard;
             wizard->setMode(BackupWizard::Mode::Backup);
             wizard->setPath(m_backupPath);
             wizard->next();
         },
         [this] {
             auto* wizard = static_cast<BackupWizard*>(m_dialog);
             return wizard->progressPage()->isComplete();
         },
         [this] { return m_dialog; }},
        {QStringLiteral("10-terminal"),
         [this, w] {
             m_dialog->close();
             w->showSection(MainWindow::Terminal);
             w->terminalPage()->send(QStringLiteral("?IFGWG"));
             w->terminalPage()->send(QStringLiteral("?AMAX"));
         },
         [w] { return w->terminalPage()->logText().count(QLatin1Char('\n')) >= 6; },
         {}},
    };
}

void ScreenshotTour::runStep(int index) {
    if (index >= m_steps.size()) {
        Q_EMIT finished(m_failures.isEmpty());
        return;
    }
    m_steps[index].prepare();
    waitFor(index, 0);
}

void ScreenshotTour::waitFor(int index, int waitedMs) {
    const Step& step = m_steps[index];
    if (!step.ready() && waitedMs < kStepTimeoutMs) {
        QTimer::singleShot(kPollMs, this,
                           [this, index, waitedMs] { waitFor(index, waitedMs + kPollMs); });
        return;
    }
    if (waitedMs >= kStepTimeoutMs) {
        m_failures << QStringLiteral("%1: its data did not arrive within %2 s (%3)")
                          .arg(step.name)
                          .arg(kStepTimeoutMs / 1000)
                          .arg(m_shell->window()->lastMessage());
    }
    // One more round of the event loop so the page paints what arrived.
    QTimer::singleShot(300, this, [this, index] {
        capture(index);
        runStep(index + 1);
    });
}

void ScreenshotTour::capture(int index) {
    MainWindow* w = m_shell->window();
    QPixmap shot = w->grab();
    if (const auto& overlay = m_steps[index].overlay) {
        QWidget* dialog = overlay();
        const QPixmap top = dialog->grab();
        QPainter painter(&shot);
        painter.fillRect(shot.rect(), QColor(0, 0, 0, 80));
        const QPoint at((shot.width() - top.width()) / 2, (shot.height() - top.height()) / 2);
        painter.drawPixmap(at, top);
        painter.setPen(w->palette().color(QPalette::Mid));
        painter.drawRect(QRect(at, top.size()).adjusted(-1, -1, 0, 0));
    }
    const QString path = QDir(m_directory).filePath(m_steps[index].name + QStringLiteral(".png"));
    if (!shot.save(path))
        m_failures << QStringLiteral("%1: cannot write %2").arg(m_steps[index].name, path);
    qCInfo(shellLog) << "screenshot" << path;
}

}  // namespace cambench
