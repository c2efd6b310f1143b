#include "camcon_window.h"

#include "analogue_cams_page.h"
#include "backup_page.h"
#include "backup_wizard.h"
#include "cam_page.h"
#include "camcon_gui.h"
#include "camcon_identity_panel.h"
#include "capability_gate.h"
#include "compare_dialog.h"
#include "compare_programs_dialog.h"
#include "dead_time_modes_page.h"
#include "dead_times_page.h"
#include "device_check.h"
#include "device_reads.h"
#include "eeprom_lock_page.h"
#include "line_backup_dialog.h"
#include "monitor_page.h"
#include "plc_coupling_page.h"
#include "plc_page.h"
#include "programming_program_page.h"
#include "settings_page.h"
#include "terminal_page.h"
#include "users_page.h"
#include "workspace.h"

#include "ui/camcon/cameditor/cam_editor_widget.h"
#include "ui/device_session.h"
#include "ui/main_window.h"
#include "ui/sentence.h"

#include <QAction>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QTimer>

namespace cambench {

CamConWindow::CamConWindow(CamConGui* gui, MainWindow* window)
    : FamilyWindow(gui, window), m_camcon(gui), m_workspace(gui->workspace()) {
    createPages();
    // Its polls would make the status bar's job display flicker.
    window->addQuietJobTitle(MonitorPage::tr("Monitor"));
}

CamConWindow::~CamConWindow() = default;

void CamConWindow::createPages() {
    DeviceSession* session = gui()->session();
    m_cams = new CamPage(session, m_workspace);
    m_deadTimes = new DeadTimesPage(session, m_workspace);
    m_settings = new SettingsPage(session, m_workspace);
    m_users = new UsersPage(session, m_workspace);
    m_plc = new PlcPage(session, m_workspace);
    m_monitor = new MonitorPage(session, m_workspace);
    auto* backup = new BackupPage;
    m_terminal = new TerminalPage(session);
    // Sections some protocols lack say so (CapabilityGate); those only the
    // table interface has come last.
    using Cap = comm::CamConCapability;
    const auto gate = [session](CamConSectionPage* page, Cap capability) {
        return new CapabilityGate(session, page, capability);
    };
    m_pages = {m_cams,
               m_deadTimes,
               m_settings,
               gate(m_users, Cap::Users),
               gate(m_plc, Cap::PlcNetworks),
               m_monitor,
               gate(backup, Cap::EepromBackup),
               gate(m_terminal, Cap::Terminal),
               gate(new DeadTimeModesPage(session, m_workspace), Cap::DeadTimeModes),
               gate(new AnalogueCamsPage(session, m_workspace), Cap::AnalogueCams),
               gate(new ProgrammingProgramPage(session, m_workspace), Cap::ProgrammingProgram),
               gate(new EepromLockPage(session, m_workspace), Cap::EepromLock),
               gate(new PlcCouplingPage(session, m_workspace), Cap::ShortCommands)};
    connect(backup, &BackupPage::wizardRequested, this, &CamConWindow::openBackupWizard);
    connect(m_monitor, &MonitorPage::statusUpdated, m_cams, &CamPage::showStatus);
    connect(m_monitor, &MonitorPage::liveEnded, m_cams, &CamPage::clearLive);
}

QList<SectionPage*> CamConWindow::pages() const {
    return m_pages;
}

SectionPage* CamConWindow::sectionPage(Section section) const {
    return m_pages.value(section);
}

void CamConWindow::showSection(Section section) {
    window()->showPage(sectionPage(section));
}

QList<CamConSectionPage*> CamConWindow::dataPages() const {
    // The gates: nothing to compare where the protocol lacks the section.
    QList<CamConSectionPage*> pages{m_cams, m_deadTimes, m_settings};
    for (Section section :
         {Users, Plc, DeadTimeModes, AnalogueCams, ProgrammingProgram, EepromLock})
        pages << static_cast<CamConSectionPage*>(m_pages.at(section));
    return pages;
}

QWidget* CamConWindow::identityPanel() {
    if (!m_identity) m_identity = new CamConIdentityPanel(gui()->session(), m_workspace);
    return m_identity;
}

void CamConWindow::addMenuEntries(const FamilyMenus& menus) {
    addFileEntries(menus.file);

    CamEditorWidget* editor = m_cams->editor();
    editor->undoAction()->setShortcut(QKeySequence::Undo);
    // Ctrl+Y as well: what most Windows programs and many technicians use.
    editor->redoAction()->setShortcuts(
        {QKeySequence(QKeySequence::Redo), QKeySequence(Qt::CTRL | Qt::Key_Y)});
    menus.edit->addAction(editor->undoAction());
    menus.edit->addAction(editor->redoAction());
    menus.edit->addSeparator();
    menus.edit->addActions(editor->editorActions());

    menus.tools->addAction(tr("Compare &programs…"), this, &CamConWindow::openComparePrograms);

    QMenu* device = menus.device;
    device->addAction(tr("&Read everything"), this,
                      [this] { readEverything(m_cams->editor()->currentProgram()); });
    device->addSeparator();
    device->addAction(tr("Co&mpare with device…"), this, &CamConWindow::openCompare);
    QAction* backup =
        device->addAction(tr("&Backup and restore…"), this, &CamConWindow::openBackupWizard);
    QAction* lineBackup = device->addAction(tr("Back up all devices on this &line…"), this,
                                            &CamConWindow::openLineBackup);
    // Greyed with the Backup section where the protocol has no EEPROM backup
    // (the table interface), with the reason as the tooltip.
    if (auto* gate = qobject_cast<CapabilityGate*>(m_pages.at(Backup))) {
        const auto follow = [gate, backup, lineBackup](bool available) {
            for (QAction* action : {backup, lineBackup}) {
                action->setEnabled(available);
                action->setToolTip(gate->reason());
            }
        };
        connect(gate, &CapabilityGate::availabilityChanged, this, follow);
        follow(gate->isAvailable());
    }
}

void CamConWindow::pageShown(SectionPage* page) {
    m_monitor->setLiveWanted(page == m_monitor || page == m_cams);
}

void CamConWindow::showMessage(const QString& text) {
    window()->showMessage(text);
}

void CamConWindow::deviceOnLine(bool load) {
    if (load) m_pendingProgram = 0;
    checkDevice();
}

void CamConWindow::checkDevice() {
    DeviceSession* session = gui()->session();
    ++m_startReads;
    checkConnectedDevice(
        window(), session, m_workspace, [this, session](const Status& status, bool other) {
            --m_startReads;
            const int pending = m_pendingProgram;
            m_pendingProgram = -1;
            if (!status) {
                if (status.error().kind != ErrorKind::Cancelled) {
                    session->setIdentifyFailed(status.error().message);
                    showMessage(tr("The device did not identify itself: %1 Your edits are kept.")
                                    .arg(asSentence(status.error().message)));
                    if (pending >= 0) window()->reportLoaded(false);
                }
                // Still on the line: asked again shortly (an identity read has no
                // side effect); until it answers, nothing is written.
                if (session->isOnline()) {
                    m_pendingProgram = pending;
                    constexpr int kRecheckMs = 2000;
                    QTimer::singleShot(kRecheckMs, this, [this, session] {
                        if (session->isOnline() && !session->deviceChecked() &&
                            sessionFamily(*session) == gui()->familyId())
                            checkDevice();
                    });
                }
                return;
            }
            if (other)
                showMessage(m_workspace->otherDeviceNote() + QLatin1Char(' ') +
                            tr("The start pages are read from it; the rest says \"not read\" "
                               "until Read everything or Compare."));
            // Another device: what a technician looks at first is read from it
            // (asking where that would replace edits).
            if (pending >= 0 || other)
                readStartSections(pending >= 0 ? pending : m_cams->editor()->currentProgram());
        });
}

void CamConWindow::readStartSections(int program) {
    // What a technician looks at first; the other programs stay "not read"
    // until Device → Read everything (that takes long on a slow line).
    showMessage(tr("Reading the device…"));
    const int shown = std::clamp(program, 0, std::max(0, m_workspace->info().programs - 1));
    m_cams->editor()->setCurrentProgram(shown);
    // The sections some protocols lack (and only those) read here; a
    // section the protocol lacks says so on its page, not as a failure.
    for (SectionPage* page : m_pages) page->deviceConnected();
    const auto finished = [this](const Status& status) {
        if (!status && status.error().kind != ErrorKind::Cancelled &&
            status.error().kind != ErrorKind::Usage &&
            status.error().kind != ErrorKind::Unsupported)
            showMessage(tr("Reading the device: %1").arg(status.error().message));
        if (--m_startReads > 0) return;
        window()->reportLoaded(true);
    };
    DeviceSession* session = gui()->session();
    m_startReads += 4;
    devicereads::readSettings(window(), session, m_workspace, finished);
    devicereads::readOutputSettings(window(), session, m_workspace, finished);
    devicereads::readUsers(window(), session, m_workspace, finished);
    m_cams->readProgram(shown, finished);
}

void CamConWindow::readEverything(int program) {
    if (m_readJob != 0) return;  // one whole-device read at a time
    showMessage(tr("Reading everything the device holds…"));
    m_readJob = devicereads::readEverything(
        window(), gui()->session(), m_workspace,
        [this, program](const Status& status, const QStringList& skipped) {
            m_readJob = 0;
            if (status) {
                m_cams->editor()->setCurrentProgram(
                    std::clamp(program, 0, std::max(0, m_workspace->info().programs - 1)));
                showMessage(skipped.isEmpty() ? tr("Everything read from the device.")
                                              : tr("Read from the device, except: %1")
                                                    .arg(skipped.join(QLatin1Char(' '))));
            } else if (status.error().kind == ErrorKind::Cancelled) {
                showMessage(tr("Reading the device: %1").arg(status.error().message));
            } else {
                showMessage(tr("Reading the device failed: %1 Your edits are kept.")
                                .arg(asSentence(status.error().message)));
            }
            Q_EMIT everythingRead(status.ok());
        });
}

CompareDialog* CamConWindow::openCompare() {
    auto* dialog = new CompareDialog(gui()->session(), m_workspace, dataPages(), window());
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &CompareDialog::writeFinished, this, [this](const WriteResult& result) {
        showMessage(tr("Write: %1").arg(writeSummary(result)));
    });
    dialog->show();
    return dialog;
}

CompareProgramsDialog* CamConWindow::openComparePrograms() {
    auto* dialog = new CompareProgramsDialog(gui()->session(), m_workspace, window());
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setSide(0, dialog->sideSource(0), m_cams->editor()->currentProgram());
    dialog->setSide(1, dialog->sideSource(1), m_cams->editor()->currentProgram());
    dialog->show();
    // The program on screen against the device (or, offline, a file to choose).
    if (gui()->session()->isOnline()) dialog->compare();
    return dialog;
}

BackupWizard* CamConWindow::openBackupWizard() {
    auto* wizard = new BackupWizard(gui()->session(), m_workspace, window());
    wizard->setAttribute(Qt::WA_DeleteOnClose);
    connect(wizard, &BackupWizard::restored, this, [this] { readEverything(0); });
    wizard->show();
    return wizard;
}

LineBackupDialog* CamConWindow::openLineBackup() {
    auto* dialog = new LineBackupDialog(gui()->session(), window());
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
    return dialog;
}

bool CamConWindow::confirmClose() {
    const int changes = m_workspace->changedCount();
    if (changes == 0) return true;
    QMessageBox box(
        QMessageBox::Warning, tr("Unwritten changes"),
        tr("%n change(s) are not written to the device. Close anyway?", nullptr, changes),
        QMessageBox::NoButton, window());
    QPushButton* compare = box.addButton(tr("Compare with device…"), QMessageBox::AcceptRole);
    QPushButton* save = box.addButton(tr("Save project…"), QMessageBox::ActionRole);
    box.addButton(tr("Close without writing"), QMessageBox::DestructiveRole);
    QPushButton* cancel = box.addButton(QMessageBox::Cancel);
    box.setDefaultButton(cancel);
    box.exec();
    if (box.clickedButton() == compare) {
        openCompare();
        return false;
    }
    if (box.clickedButton() == save) {
        saveProject();
        return m_workspace->changedCount() == 0 || !m_workspace->projectPath().isEmpty();
    }
    return box.clickedButton() != cancel;
}

}  // namespace cambench
