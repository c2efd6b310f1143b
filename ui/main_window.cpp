#include "main_window.h"

#include "connection_page.h"
#include "connection_status.h"
#include "device_session.h"
#include "family_pages.h"
#include "gui_settings.h"
#include "language.h"
#include "last_write_report.h"
#include "report_dialog.h"
#include "theme.h"
#include "ui/camcon/analogue_cams_page.h"
#include "ui/camcon/backup_page.h"
#include "ui/camcon/backup_wizard.h"
#include "ui/camcon/cam_page.h"
#include "ui/camcon/capability_gate.h"
#include "ui/camcon/commissioning_report.h"
#include "ui/camcon/compare_dialog.h"
#include "ui/camcon/dead_time_modes_page.h"
#include "ui/camcon/dead_times_page.h"
#include "ui/camcon/device_check.h"
#include "ui/camcon/device_reads.h"
#include "ui/camcon/eeprom_lock_page.h"
#include "ui/camcon/incoming_values.h"
#include "ui/camcon/line_backup_dialog.h"
#include "ui/camcon/monitor_page.h"
#include "ui/camcon/new_project_dialog.h"
#include "ui/camcon/plc_coupling_page.h"
#include "ui/camcon/plc_page.h"
#include "ui/camcon/programming_program_page.h"
#include "ui/camcon/project_io.h"
#include "ui/camcon/settings_page.h"
#include "ui/camcon/terminal_page.h"
#include "ui/camcon/users_page.h"
#include "ui/camcon/workspace.h"

#include "ui/camcon/cameditor/cam_editor_widget.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFrame>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTimer>
#include <QToolButton>

namespace cambench {

MainWindow::MainWindow(DeviceSession* session, Workspace* workspace, QWidget* parent)
    : QMainWindow(parent),
      m_session(session),
      m_workspace(workspace),
      m_nav(new QListWidget),
      m_stack(new QStackedWidget),
      m_strip(new ConnectionStrip(session, workspace)),
      m_indicator(new ConnectionIndicator(session)),
      m_jobLabel(new QLabel),
      m_jobProgress(new QProgressBar),
      m_jobCancel(new QToolButton),
      m_lastWrite(new QToolButton) {
    createPages();
    createMenus();
    createStatusBar();

    m_nav->setMaximumWidth(220);
    m_nav->setMinimumWidth(170);
    auto* body = new QHBoxLayout;
    body->addWidget(m_nav);
    body->addWidget(m_stack, 1);
    auto* central = new QWidget;
    auto* layout = new QVBoxLayout(central);
    // A lost or silent line is reported where the user looks, with the way back.
    layout->addWidget(m_strip);
    layout->addLayout(body, 1);
    setCentralWidget(central);

    connect(m_nav, &QListWidget::currentRowChanged, m_stack, &QStackedWidget::setCurrentIndex);
    connect(m_nav, &QListWidget::currentRowChanged, this, &MainWindow::updateLivePolling);
    connect(m_session, &DeviceSession::stateChanged, this, &MainWindow::updateConnection);
    connect(m_session, &DeviceSession::targetChanged, this, [this] {
        if (m_session->isOnline()) checkDevice();
    });
    connect(m_session, &DeviceSession::reconnected, this, [this] {
        showMessage(
            tr("Connection re-established. Your edits are unchanged; Compare with "
               "device reads what the device holds now."));
    });
    connect(m_workspace, &Workspace::changedCountChanged, this, &MainWindow::updateTitle);
    connect(m_workspace, &Workspace::infoChanged, this, &MainWindow::updateTitle);
    connect(m_workspace, &Workspace::projectPathChanged, this, &MainWindow::updateTitle);
    m_nav->setCurrentRow(Connection);
    updateConnection();
    updateTitle();
    resize(1280, 800);
    updateLivePolling();
}

MainWindow::~MainWindow() = default;

void MainWindow::createPages() {
    m_connection = new ConnectionPage(m_session, m_workspace);
    m_cams = new CamPage(m_session, m_workspace);
    m_deadTimes = new DeadTimesPage(m_session, m_workspace);
    m_settings = new SettingsPage(m_session, m_workspace);
    m_users = new UsersPage(m_session, m_workspace);
    m_plc = new PlcPage(m_session, m_workspace);
    m_monitor = new MonitorPage(m_session, m_workspace);
    auto* backup = new BackupPage;
    m_terminal = new TerminalPage(m_session);
    // Sections some protocols lack say so (CapabilityGate); those only the
    // table interface has come last.
    using Cap = comm::CamConCapability;
    const auto gate = [this](SectionPage* page, Cap capability) {
        return new CapabilityGate(m_session, page, capability);
    };
    m_pages = {m_connection,
               m_cams,
               m_deadTimes,
               m_settings,
               gate(m_users, Cap::Users),
               gate(m_plc, Cap::PlcNetworks),
               m_monitor,
               gate(backup, Cap::EepromBackup),
               gate(m_terminal, Cap::Terminal),
               gate(new DeadTimeModesPage(m_session, m_workspace), Cap::DeadTimeModes),
               gate(new AnalogueCamsPage(m_session, m_workspace), Cap::AnalogueCams),
               gate(new ProgrammingProgramPage(m_session, m_workspace), Cap::ProgrammingProgram),
               gate(new EepromLockPage(m_session, m_workspace), Cap::EepromLock),
               gate(new PlcCouplingPage(m_session, m_workspace), Cap::ShortCommands)};
    // The sections above are the CamCon's (the connection page the shell's);
    // other families' pages come from their registration.
    m_pageFamilies.fill(QStringLiteral("camcon"), m_pages.size());
    m_pageFamilies[Connection] = QString();
    for (const FamilyPage& registered : FamilyPageRegistry::instance().all()) {
        m_pages << registered.create(m_session);
        m_pageFamilies << registered.familyId;
    }
    for (SectionPage* page : m_pages) {
        m_stack->addWidget(page);
        m_nav->addItem(page->sectionTitle());
        if (auto* gated = qobject_cast<CapabilityGate*>(page))
            gated->setNavItem(m_nav->item(m_nav->count() - 1));
        connect(page, &SectionPage::statusMessage, this, &MainWindow::showMessage);
    }
    connect(backup, &BackupPage::wizardRequested, this, &MainWindow::openBackupWizard);
    connect(m_monitor, &MonitorPage::statusUpdated, m_cams, &CamPage::showStatus);
    connect(m_monitor, &MonitorPage::liveEnded, m_cams, &CamPage::clearLive);
    connect(m_connection, &ConnectionPage::deviceSelected, this, [this] { readAtStart(0); });
    showFamilyPages();
}

void MainWindow::showFamilyPages() {
    const QString family = sessionFamily(*m_session);
    for (int row = 0; row < m_pages.size(); ++row) {
        const QString& pageFamily = m_pageFamilies.at(row);
        m_nav->item(row)->setHidden(!pageFamily.isEmpty() && pageFamily != family);
    }
    if (m_nav->currentItem() && m_nav->currentItem()->isHidden()) showSection(Connection);
}

void MainWindow::identifyOtherFamily() {
    m_session->worker().run<Result<QString>>(
        this, comm::JobPriority::User, tr("Identify device"),
        [](comm::JobContext& job) -> Result<QString> {
            if (!job.device()) return Error::communication(tr("not connected"));
            return job.device()->identify();
        },
        [this](Result<QString> identity) {
            const int pending = m_pendingProgram;
            m_pendingProgram = -1;
            showMessage(identity ? tr("Connected: %1").arg(*identity)
                                 : tr("The device did not identify itself: %1")
                                       .arg(asSentence(identity.error().message)));
            if (pending >= 0) Q_EMIT loaded(identity.ok());
        });
}

QList<SectionPage*> MainWindow::dataPages() const {
    // The gates: nothing to compare where the protocol lacks the section.
    return {m_cams,
            m_deadTimes,
            m_settings,
            m_pages.at(Users),
            m_pages.at(Plc),
            m_pages.at(DeadTimeModes),
            m_pages.at(AnalogueCams),
            m_pages.at(ProgrammingProgram),
            m_pages.at(EepromLock)};
}

void MainWindow::createMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&New project…"), this, &MainWindow::newProject);
    file->addAction(tr("&Open project…"), QKeySequence::Open, this, &MainWindow::openProject);
    m_recentMenu = file->addMenu(tr("Recent &files"));
    connect(m_recentMenu, &QMenu::aboutToShow, this, &MainWindow::fillRecentFiles);
    fillRecentFiles();
    file->addAction(tr("&Save project"), QKeySequence::Save, this, &MainWindow::saveProject);
    file->addAction(tr("Save project &as…"), QKeySequence::SaveAs, this,
                    &MainWindow::saveProjectAs);
    file->addSeparator();
    file->addAction(tr("Commissioning &report (PDF)…"), this, &MainWindow::exportReportInteractive);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    CamEditorWidget* editor = m_cams->editor();
    editor->undoAction()->setShortcut(QKeySequence::Undo);
    // Ctrl+Y as well: what most Windows programs and many technicians use.
    editor->redoAction()->setShortcuts(
        {QKeySequence(QKeySequence::Redo), QKeySequence(Qt::CTRL | Qt::Key_Y)});
    edit->addAction(editor->undoAction());
    edit->addAction(editor->redoAction());
    edit->addSeparator();
    edit->addActions(editor->editorActions());

    QMenu* device = menuBar()->addMenu(tr("&Device"));
    device->addAction(tr("&Connect"), this, [this] {
        m_session->connectTo(m_connection->connectionSettings(), m_connection->protocolSettings());
    });
    device->addAction(tr("&Disconnect"), m_session, &DeviceSession::disconnectFromDevice);
    device->addAction(tr("&Read everything"), this,
                      [this] { readEverything(m_cams->editor()->currentProgram()); });
    device->addSeparator();
    device->addAction(tr("Co&mpare with device…"), this, &MainWindow::openCompare);
    QAction* lastWrite =
        device->addAction(tr("&Last write report…"), this, &MainWindow::showLastWriteReport);
    lastWrite->setEnabled(!LastWriteReport::instance().isEmpty());
    connect(&LastWriteReport::instance(), &LastWriteReport::changed, lastWrite,
            [lastWrite] { lastWrite->setEnabled(true); });
    QAction* backup =
        device->addAction(tr("&Backup and restore…"), this, &MainWindow::openBackupWizard);
    QAction* lineBackup = device->addAction(tr("Back up all devices on this &line…"), this,
                                            &MainWindow::openLineBackup);
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

    QMenu* view = menuBar()->addMenu(tr("&View"));
    QAction* dark = view->addAction(tr("&Dark palette"));
    dark->setCheckable(true);
    dark->setChecked(isDarkTheme());
    connect(dark, &QAction::toggled, this, [this](bool on) {
        applyTheme(on);
        guisettings::setDark(on);
        Q_EMIT darkRequested(on);
    });
    QMenu* language = view->addMenu(tr("&Language"));
    auto* group = new QActionGroup(language);
    const QList<QPair<QString, QString>> languages{
        {QStringLiteral("en"), QStringLiteral("English")},
        {QStringLiteral("de"), QStringLiteral("Deutsch")}};
    for (const auto& [code, name] : languages) {
        QAction* action = language->addAction(name);
        action->setCheckable(true);
        action->setChecked(currentLanguage() == code);
        group->addAction(action);
        const QString lang = code;
        connect(action, &QAction::triggered, this,
                [this, lang] { Q_EMIT languageRequested(lang); });
    }
    view->addSeparator();
    for (int i = 0; i < m_pages.size(); ++i) {
        // "Encoder & system" would make "&s" a mnemonic: double the ampersand.
        QString title = m_pages[i]->sectionTitle();
        view->addAction(title.replace(QLatin1Char('&'), QLatin1String("&&")), this,
                        [this, i] { showSection(Section(i)); });
    }

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About CamBench"), this, [this] {
        QMessageBox::about(
            this, tr("About CamBench"),
            tr("<b>CamBench %1</b><p>Programming, monitoring and backup of Digitronic "
               "CamCon electronic cam controllers.</p>")
                .arg(QStringLiteral(CAMBENCH_VERSION)));
    });
}

void MainWindow::createStatusBar() {
    m_jobProgress->setMaximumWidth(180);
    m_jobProgress->setTextVisible(false);
    m_jobProgress->hide();
    statusBar()->addPermanentWidget(m_jobLabel);
    statusBar()->addPermanentWidget(m_jobProgress);
    statusBar()->addPermanentWidget(m_indicator);
    // The last write's report stays one click away after its status line is
    // gone (10 s) and its dialog closed.
    m_lastWrite->setObjectName(QStringLiteral("lastWriteReport"));
    m_lastWrite->setAutoRaise(true);
    statusBar()->insertPermanentWidget(0, m_lastWrite);
    connect(m_lastWrite, &QToolButton::clicked, this, &MainWindow::showLastWriteReport);
    connect(&LastWriteReport::instance(), &LastWriteReport::changed, this,
            &MainWindow::updateLastWriteButton);
    updateLastWriteButton();
    comm::CommWorker& worker = m_session->worker();
    m_jobCancel->setText(tr("Cancel"));
    m_jobCancel->setToolTip(tr("Cancel what the device is doing for you now."));
    m_jobCancel->hide();
    statusBar()->insertPermanentWidget(2, m_jobCancel);
    connect(m_jobCancel, &QToolButton::clicked, this, [this] {
        if (m_runningJob != 0) m_session->worker().cancel(m_runningJob);
    });
    connect(&worker, &comm::CommWorker::jobStarted, this, [this](quint64 id, const QString& title) {
        if (title == MonitorPage::tr("Monitor")) return;  // polls would make the bar flicker
        m_runningJob = id;
        m_jobLabel->setText(title);
        m_jobProgress->setRange(0, 0);
        m_jobProgress->show();
        m_jobCancel->show();
    });
    connect(&worker, &comm::CommWorker::jobProgress, this,
            [this](quint64 id, qint64 done, qint64 total, const QString&) {
                if (id != m_runningJob || total <= 0) return;
                m_jobProgress->setRange(0, 1000);
                m_jobProgress->setValue(int(done * 1000 / total));
            });
    connect(&worker, &comm::CommWorker::jobFinished, this, [this](quint64 id) {
        if (id != m_runningJob) return;
        m_runningJob = 0;
        m_jobLabel->clear();
        m_jobProgress->hide();
        m_jobCancel->hide();
        // "Reading …" is over once its job is: its outcome replaces it, or
        // nothing does (a job without a message of its own).
        if (statusBar()->currentMessage().endsWith(QChar(0x2026))) statusBar()->clearMessage();
    });
}

void MainWindow::showSection(Section section) {
    m_nav->setCurrentRow(section);
}

void MainWindow::updateLivePolling() {
    // Only pages that show live values keep the line busy with polls.
    const Section section = currentSection();
    m_monitor->setLiveWanted(section == Monitor || section == Cams);
}

MainWindow::Section MainWindow::currentSection() const {
    return Section(m_stack->currentIndex());
}

void MainWindow::updateLastWriteButton() {
    const LastWriteReport& report = LastWriteReport::instance();
    m_lastWrite->setVisible(!report.isEmpty());
    if (report.isEmpty()) return;
    m_lastWrite->setText(
        report.complete()
            ? tr("Last write (%1): complete")
                  .arg(QLocale().toString(report.when().time(), QLocale::ShortFormat))
            : tr("Last write (%1): NOT complete")
                  .arg(QLocale().toString(report.when().time(), QLocale::ShortFormat)));
    m_lastWrite->setToolTip(tr("Show the report of the last write: %1").arg(report.summary()));
}

void MainWindow::showLastWriteReport() {
    const LastWriteReport& report = LastWriteReport::instance();
    if (report.isEmpty()) return;
    ReportDialog::present(
        this, report.complete() ? QMessageBox::Information : QMessageBox::Warning, report.title(),
        tr("%1 (written at %2)")
            .arg(report.summary(), QLocale().toString(report.when(), QLocale::ShortFormat)),
        report.details());
}

void MainWindow::showMessage(const QString& message) {
    const QString text = withoutCommandNames(message);
    m_lastMessage = text;
    // Long enough to read twice, short enough not to describe a past state.
    constexpr int kMessageMs = 10000;
    statusBar()->showMessage(text, kMessageMs);
}

void MainWindow::updateTitle() {
    const int changes = m_workspace->changedCount();
    const QString projectPath = m_workspace->projectPath();
    QString where = projectPath.isEmpty() ? QString() : QFileInfo(projectPath).fileName();
    if (where.isEmpty()) {
        where = m_workspace->infoFromDevice() ? tr("CamCon %1 (device %2)")
                                                    .arg(m_workspace->info().epromDate)
                                                    .arg(m_workspace->info().deviceNumber)
                                              : tr("offline project");
    }
    QString title = tr("CamBench – %1").arg(where) + QStringLiteral("[*]");
    if (changes > 0) title += QLatin1Char(' ') + tr("[%n change(s) not written]", nullptr, changes);
    setWindowTitle(title);
    setWindowModified(changes > 0);
}

void MainWindow::updateConnection() {
    const comm::ConnectionState state = m_session->state();
    if (state == comm::ConnectionState::Lost)
        showMessage(tr("Connection lost: %1").arg(asSentence(m_session->lastMessage())));
    showFamilyPages();
    // Every connect and reconnect may reach another device.
    if (state == comm::ConnectionState::Connected) checkDevice();
    // A connect that failed (a user's disconnect carries no message).
    if (state == comm::ConnectionState::Disconnected && !m_session->lastMessage().isEmpty() &&
        !m_session->isRetrying()) {
        showMessage(tr("Not connected: %1").arg(m_session->lastMessage()));
        if (m_pendingProgram >= 0) {
            m_pendingProgram = -1;
            Q_EMIT loaded(false);
        }
    }
}

void MainWindow::connectAndLoad(int program) {
    m_pendingProgram = program;
    m_session->connectTo(m_connection->connectionSettings(), m_connection->protocolSettings());
}

void MainWindow::readAtStart(int program) {
    m_pendingProgram = program;
    if (m_session->isOnline()) checkDevice();
}

void MainWindow::checkDevice() {
    // The CamCon's pages read its sections; another family's read their own.
    if (sessionFamily(*m_session) != QLatin1String("camcon")) {
        identifyOtherFamily();
        return;
    }
    ++m_startReads;
    checkConnectedDevice(this, m_session, m_workspace, [this](const Status& status, bool other) {
        --m_startReads;
        const int pending = m_pendingProgram;
        m_pendingProgram = -1;
        if (!status) {
            if (status.error().kind != ErrorKind::Cancelled) {
                showMessage(tr("The device did not identify itself: %1 Your edits are kept.")
                                .arg(asSentence(status.error().message)));
                if (pending >= 0) Q_EMIT loaded(false);
            }
            // Still on the line: asked again shortly (an identity read has no
            // side effect); until it answers, nothing is written.
            if (m_session->isOnline()) {
                m_pendingProgram = pending;
                constexpr int kRecheckMs = 2000;
                QTimer::singleShot(kRecheckMs, this, [this] {
                    if (m_session->isOnline() && !m_session->deviceChecked()) checkDevice();
                });
            }
            return;
        }
        if (other) showMessage(m_workspace->otherDeviceNote());
        // Another device: what a technician looks at first is read from it
        // (asking where that would replace edits).
        if (pending >= 0 || other)
            readStartSections(pending >= 0 ? pending : m_cams->editor()->currentProgram());
    });
}

void MainWindow::readStartSections(int program) {
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
            status.error().kind != ErrorKind::Usage)
            showMessage(tr("Reading the device: %1").arg(status.error().message));
        if (--m_startReads > 0) return;
        Q_EMIT loaded(true);
    };
    m_startReads += 4;
    devicereads::readSettings(this, m_session, m_workspace, finished);
    devicereads::readOutputSettings(this, m_session, m_workspace, finished);
    devicereads::readUsers(this, m_session, m_workspace, finished);
    m_cams->readProgram(shown, finished);
}

void MainWindow::readEverything(int program) {
    if (m_readJob != 0) return;  // one whole-device read at a time
    showMessage(tr("Reading everything the device holds…"));
    m_readJob = devicereads::readEverything(
        this, m_session, m_workspace,
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

CompareDialog* MainWindow::openCompare() {
    auto* dialog = new CompareDialog(m_session, m_workspace, dataPages(), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &CompareDialog::writeFinished, this, [this](const WriteResult& result) {
        showMessage(tr("Write: %1").arg(writeSummary(result)));
    });
    dialog->show();
    return dialog;
}

BackupWizard* MainWindow::openBackupWizard() {
    auto* wizard = new BackupWizard(m_session, m_workspace, this);
    wizard->setAttribute(Qt::WA_DeleteOnClose);
    connect(wizard, &BackupWizard::restored, this, [this] { readEverything(0); });
    wizard->show();
    return wizard;
}

LineBackupDialog* MainWindow::openLineBackup() {
    auto* dialog = new LineBackupDialog(m_session, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
    return dialog;
}

bool MainWindow::confirmClose() {
    const int changes = m_workspace->changedCount();
    if (changes == 0) return true;
    QMessageBox box(
        QMessageBox::Warning, tr("Unwritten changes"),
        tr("%n change(s) are not written to the device. Close anyway?", nullptr, changes),
        QMessageBox::NoButton, this);
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

void MainWindow::closeEvent(QCloseEvent* event) {
    if (confirmClose()) {
        guisettings::saveWindow(*this, currentSection());
        event->accept();
    } else {
        event->ignore();
    }
}

void MainWindow::newProject() {
    NewProjectDialog dialog(m_workspace->info(), this);
    if (dialog.exec() != QDialog::Accepted) return;
    if (m_workspace->changedCount() > 0 &&
        QMessageBox::question(this, tr("New project"),
                              tr("%n change(s) are not written or saved. Discard them for a new, "
                                 "empty project?",
                                 nullptr, m_workspace->changedCount())) != QMessageBox::Yes)
        return;
    m_session->disconnectFromDevice();
    m_workspace->clear(emptyProject(dialog.capacities()).device);
    m_workspace->setProjectPath({});
    showSection(Cams);
}

void MainWindow::openProject() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open project"), QString(),
                                                      tr("CamBench projects (*.json)"));
    if (!path.isEmpty()) openProjectFile(path);
}

void MainWindow::openProjectFile(const QString& path) {
    const Result<Project> project = loadProject(path);
    if (!project) {
        ReportDialog::present(this, QMessageBox::Warning, tr("Open project"),
                              tr("The project %1 was not opened.").arg(path),
                              project.error().message);
        if (!QFileInfo::exists(path)) guisettings::removeRecentProject(path);
        return;
    }
    if (!takeIncoming(this, *m_workspace, project.value(), ValueSource::File)) {
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

void MainWindow::fillRecentFiles() {
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

void MainWindow::saveProject() {
    if (m_workspace->projectPath().isEmpty()) {
        saveProjectAs();
    } else {
        saveProjectTo(m_workspace->projectPath());
    }
}

void MainWindow::saveProjectAs() {
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save project"), m_workspace->projectPath(), tr("CamBench projects (*.json)"));
    if (!path.isEmpty()) saveProjectTo(path);
}

Status MainWindow::saveProjectTo(const QString& path) {
    if (isReadingDevice()) {
        // Half a device in a file would look like a whole one later.
        const Status refused =
            Error::usage(tr("The device is still being read; the project was not "
                            "saved. Save again when the reading is done."));
        ReportDialog::present(this, QMessageBox::Information, tr("Save project"),
                              refused.error().message);
        return refused;
    }
    const Project project = projectFromWorkspace(*m_workspace);
    const Status saved = cambench::saveProject(path, project);
    if (!saved) {
        ReportDialog::present(this, QMessageBox::Warning, tr("Save project"),
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

Status MainWindow::exportReport(const QString& path) {
    return CommissioningReport::write(path, *m_workspace);
}

void MainWindow::exportReportInteractive() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Commissioning report"), QString(),
                                                      tr("PDF files (*.pdf)"));
    if (path.isEmpty()) return;
    const Status written = exportReport(path);
    if (!written) {
        QMessageBox::warning(this, tr("Commissioning report"), written.error().message);
    } else {
        showMessage(tr("Report written to %1.").arg(path));
    }
}

}  // namespace cambench
