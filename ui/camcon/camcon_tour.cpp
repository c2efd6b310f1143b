// The screenshot tour's stops on a CamCon (`cambench --screenshots DIR`):
// the Standard protocol's pages and dialogs, the table interface's own
// sections and its PLC coupling, and the Cam-BUS as the PC hears it.

#include "camcon_window.h"

#include "backup_wizard.h"
#include "cam_page.h"
#include "capability_gate.h"
#include "compare_dialog.h"
#include "compare_programs_dialog.h"
#include "monitor_page.h"
#include "plc_coupling_page.h"
#include "plc_page.h"
#include "terminal_page.h"
#include "timing_bar.h"
#include "users_page.h"
#include "workspace.h"

#include "ui/camcon/cambus/cambus_settings_widget.h"
#include "ui/camcon/cambus/cambus_view_widget.h"
#include "ui/camcon/cameditor/cam_document.h"
#include "ui/camcon/cameditor/cam_editor_widget.h"
#include "ui/connection_page.h"
#include "ui/main_window.h"
#include "ui/progress_page.h"
#include "ui/screenshot_tour.h"

#include <QDir>
#include <QPointer>
#include <QUndoStack>

#include <memory>

namespace cambench {

namespace {
const QString kStandard = QStringLiteral("standard");
const QString kTable = QStringLiteral("3964r-n96");
const QString kCamBus = QStringLiteral("cambus");
}  // namespace

QList<TourVisit> CamConWindow::tourVisits() const {
    // Compare reads the whole device: a fast simulated line keeps the tour
    // short; the Cam-BUS keeps its own pace. Each reaches a CamCon of the
    // same identity (device 0), so that no page says another device
    // answered, and Standard comes first, so that its Monitor's trend holds
    // only its own device's samples.
    return {
        {QStringLiteral("camcon-standard"), QStringLiteral("sim:baud=115200"), kStandard},
        {QStringLiteral("camcon-3964r-n96"), QStringLiteral("sim:protocol=3964r-n96;baud=115200"),
         kTable},
        {QStringLiteral("camcon-cambus"), QStringLiteral("sim:protocol=cambus;devices=0,7"),
         kCamBus, 0},
    };
}

QList<TourStop> CamConWindow::tourStops(const TourVisit& visit, const QString& directory) {
    if (visit.protocol == kTable) return tableTourStops();
    if (visit.protocol == kCamBus) return camBusTourStops();
    return standardTourStops(directory);
}

void CamConWindow::tourVisitDone(const TourVisit& visit) {
    if (visit.protocol != kStandard) return;
    // The Standard stops edited (a cam, a dead time, a minimum pulse, the
    // timing shown): undone, or the next CamCon would ask whether its
    // values may replace them. The tour starts with nothing to undo.
    m_workspace->cams()->undoStack()->setIndex(0);
    m_workspace->cams()->setMinimumPulse(2, 0);
    m_cams->timingBar()->setTimingShown(false);
}

QList<TourStop> CamConWindow::tableTourStops() {
    MainWindow* w = window();
    Workspace* ws = m_workspace;
    auto* coupling = qobject_cast<PlcCouplingPage*>(
        qobject_cast<CapabilityGate*>(sectionPage(PlcCoupling))->page());
    return {
        {QStringLiteral("01-connection"),
         [w] { w->showSection(MainWindow::Connection); },
         [] { return true; },
         {}},
        {QStringLiteral("02-dead-time-modes"),
         [this] { showSection(DeadTimeModes); },
         [ws] { return !ws->deadTimeModes().device().isEmpty(); },
         {}},
        {QStringLiteral("03-analogue-cams"),
         [this] { showSection(AnalogueCams); },
         [ws] { return ws->analogueCams().deviceValue(1).has_value(); },
         {}},
        {QStringLiteral("04-programming-program"),
         [this] { showSection(ProgrammingProgram); },
         [ws] { return ws->programmingProgram().deviceValue().has_value(); },
         {}},
        {QStringLiteral("05-eeprom-lock"),
         [this] { showSection(EepromLock); },
         [ws] { return ws->eepromLock().deviceValue().has_value(); },
         {}},
        {QStringLiteral("06-plc-coupling"),
         [this, coupling] {
             showSection(PlcCoupling);
             // What a PLC's function block would see: the status, then
             // the cams of the output shown.
             coupling->readStatus();
             coupling->readTrack();
         },
         [coupling] {
             return !coupling->statusInWords().isEmpty() && !coupling->lastOutcome().isEmpty();
         },
         {}},
    };
}

QList<TourStop> CamConWindow::camBusTourStops() {
    MainWindow* w = window();
    Workspace* ws = m_workspace;
    auto* bus = w->connectionPage()->findChild<CamBusSettingsWidget*>();
    return {
        {QStringLiteral("01-connection"),
         [w] { w->showSection(MainWindow::Connection); },
         // The bus view has heard both CamCons and this PC (without a
         // scan: that asks all 64 numbers, most of them silent).
         [bus] { return bus && bus->busView()->shownUsers().size() >= 3; },
         {}},
        {QStringLiteral("02-cam-editor"),
         [this] { showSection(Cams); },
         [ws] { return ws->infoFromDevice() && ws->cams()->hasDeviceCopy(0); },
         {}},
    };
}

QList<TourStop> CamConWindow::standardTourStops(const QString& directory) {
    MainWindow* w = window();
    Workspace* ws = m_workspace;
    // The dialog a stop opened, drawn over the window and closed by the next.
    auto dialog = std::make_shared<QPointer<QWidget>>();
    const auto shown = [dialog] { return dialog->data(); };
    const auto closeDialog = [dialog] {
        if (*dialog) (*dialog)->close();
    };
    const QString backupPath = QDir(directory).filePath(QStringLiteral("screenshot-backup.json"));
    const auto loaded = [ws] { return ws->infoFromDevice() && ws->cams()->hasDeviceCopy(0); };
    return {
        scannedConnectionStop(w, loaded),
        {QStringLiteral("02-cam-editor"), [this] { showSection(Cams); }, loaded, {}},
        {QStringLiteral("03-dead-times"),
         [this] { showSection(DeadTimes); },
         [ws] { return ws->outputSettingsKnown(); },
         {}},
        {QStringLiteral("04-settings"),
         [this] { showSection(Settings); },
         [ws] { return ws->settings().known(); },
         {}},
        {QStringLiteral("05-users"),
         [this] { showSection(Users); },
         [this, ws] {
             if (ws->users().size() == 0) return false;
             m_users->selectUser(0);
             return true;
         },
         {}},
        {QStringLiteral("06-plc"),
         [this] {
             showSection(Plc);
             m_plc->showNetwork(PlcNetwork::O, 0);
             m_plc->readNetwork();
         },
         [ws] { return ws->plc().deviceValue(Workspace::plcKey(PlcNetwork::O, 0)).has_value(); },
         {}},
        {QStringLiteral("07-monitor"),
         [this] { showSection(Monitor); },
         [this] { return m_monitor->trendSamples() >= 48; },
         {}},
        {QStringLiteral("08-compare"),
         [this, ws, dialog] {
             // An edit to compare: one cam moved, one dead time changed.
             CamDocument* cams = ws->cams();
             const Track track = cams->track(0, 1);
             if (!track.cams.isEmpty()) {
                 Cam cam = track.cams.first();
                 cam.off = std::min<qint32>(cam.off + 10, ws->info().maxPosition);
                 cams->setCam(0, 1, 0, cam);
             }
             cams->setDeadTime(2, cams->deadTime(2) + 15);
             showSection(Cams);
             *dialog = openCompare();
         },
         [dialog] {
             auto* compare = qobject_cast<CompareDialog*>(dialog->data());
             return compare && !compare->isReading() && compare->differenceCount() > 0;
         },
         shown},
        {QStringLiteral("09-backup-wizard"),
         [this, dialog, closeDialog, backupPath] {
             closeDialog();
             showSection(Backup);
             BackupWizard* wizard = openBackupWizard();
             *dialog = wizard;
             wizard->setMode(BackupWizard::Mode::Backup);
             wizard->setPath(backupPath);
             wizard->next();
         },
         [dialog] {
             auto* wizard = qobject_cast<BackupWizard*>(dialog->data());
             return wizard && wizard->progressPage()->isComplete();
         },
         shown},
        {QStringLiteral("10-terminal"),
         [this, closeDialog] {
             closeDialog();
             showSection(Terminal);
             m_terminal->send(QStringLiteral("?IFGWG"));
             m_terminal->send(QStringLiteral("?AMAX"));
         },
         [this] { return m_terminal->logText().count(QLatin1Char('\n')) >= 6; },
         {}},
        {QStringLiteral("11-compare-programs"),
         [this, dialog] {
             // The moved cam of stop 08, drawn over what the device holds.
             CompareProgramsDialog* compare = openComparePrograms();
             *dialog = compare;
             compare->setSide(0, CompareProgramsDialog::Source::Device, 0);
             compare->setSide(1, CompareProgramsDialog::Source::Edited, 0);
             compare->compare();
         },
         [dialog] {
             auto* compare = qobject_cast<CompareProgramsDialog*>(dialog->data());
             return compare && !compare->isReading() && !compare->differenceTexts().isEmpty();
         },
         shown},
        {QStringLiteral("12-timing-at-speed"),
         [this, ws, closeDialog] {
             closeDialog();
             showSection(Cams);
             // The knife's valve needs 40 ms: at 300 1/min its cam is shorter.
             ws->cams()->setMinimumPulse(2, 400);
             m_cams->editor()->setCurrentProgram(0);
             m_cams->timingBar()->setSpeed(300);
             m_cams->timingBar()->setTimingShown(true);
         },
         [this] { return !m_cams->timingBar()->timing().isEmpty(); },
         {}},
    };
}

}  // namespace cambench
