#include "main_window.h"

#include "analogue_cams_page.h"
#include "backup_page.h"
#include "backup_wizard.h"
#include "cam_page.h"
#include "capability_gate.h"
#include "commissioning_report.h"
#include "compare_dialog.h"
#include "connection_page.h"
#include "dead_time_modes_page.h"
#include "dead_times_page.h"
#include "device_session.h"
#include "eeprom_lock_page.h"
#include "language.h"
#include "monitor_page.h"
#include "new_project_dialog.h"
#include "plc_page.h"
#include "programming_program_page.h"
#include "project_io.h"
#include "settings_page.h"
#include "terminal_page.h"
#include "theme.h"
#include "users_page.h"
#include "workspace.h"

#include "ui/cameditor/cam_editor_widget.h"

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
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QStackedWidget>
#include <QStatusBar>

namespace cambench {

MainWindow::MainWindow(DeviceSession* session, Workspace* workspace, QWidget* parent)
    : QMainWindow(parent),
      m_session(session),
      m_workspace(workspace),
      m_nav(new QListWidget),
      m_stack(new QStackedWidget),
      m_lostBanner(new QFrame),
      m_lostText(new QLabel),
      m_connectionLabel(new QLabel),
      m_jobLabel(new QLabel),
      m_jobProgress(new QProgressBar) {
    createPages();
    createMenus();
    createStatusBar();

    // A lost line is reported where the user looks, with the way back.
    m_lostBanner->setFrameShape(QFrame::StyledPanel);
    m_lostBanner->setAutoFillBackground(true);
    QPalette warn = m_lostBanner->palette();
    warn.setColor(QPalette::Window, QColor(0xb0, 0x3a, 0x2e));
    warn.setColor(QPalette::WindowText, Qt::white);
    m_lostBanner->setPalette(warn);
    m_lostText->setWordWrap(true);
    auto* reconnect = new QPushButton(tr("Reconnect now"));
    auto* bannerLayout = new QHBoxLayout(m_lostBanner);
    bannerLayout->addWidget(m_lostText, 1);
    bannerLayout->addWidget(reconnect);
    m_lostBanner->hide();
    connect(reconnect, &QPushButton::clicked, m_session, &DeviceSession::reconnect);

    m_nav->setMaximumWidth(220);
    m_nav->setMinimumWidth(170);
    auto* body = new QHBoxLayout;
    body->addWidget(m_nav);
    body->addWidget(m_stack, 1);
    auto* central = new QWidget;
    auto* layout = new QVBoxLayout(central);
    layout->addWidget(m_lostBanner);
    layout->addLayout(body, 1);
    setCentralWidget(central);

    connect(m_nav, &QListWidget::currentRowChanged, m_stack, &QStackedWidget::setCurrentIndex);
    connect(m_session, &DeviceSession::stateChanged, this, &MainWindow::updateConnection);
    connect(m_session, &DeviceSession::reconnected, this, [this] {
        showMessage(tr("Connection re-established. Your edits are unchanged."));
    });
    connect(m_workspace, &Workspace::changedCountChanged, this, &MainWindow::updateTitle);
    connect(m_workspace, &Workspace::infoChanged, this, &MainWindow::updateTitle);
    m_nav->setCurrentRow(Connection);
    updateConnection();
    updateTitle();
    resize(1280, 800);
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
               gate(new EepromLockPage(m_session), Cap::EepromLock)};
    for (SectionPage* page : m_pages) {
        m_stack->addWidget(page);
        m_nav->addItem(page->sectionTitle());
        if (auto* gated = qobject_cast<CapabilityGate*>(page))
            gated->setNavItem(m_nav->item(m_nav->count() - 1));
        connect(page, &SectionPage::statusMessage, this, &MainWindow::showMessage);
    }
    connect(backup, &BackupPage::wizardRequested, this, &MainWindow::openBackupWizard);
    connect(m_monitor, &MonitorPage::statusUpdated, m_cams, &CamPage::showStatus);
    connect(m_monitor, &MonitorPage::pollingStopped, m_cams, &CamPage::clearLive);
    connect(m_connection, &ConnectionPage::deviceSelected, this, [this] { readEverything(0); });
}

QList<SectionPage*> MainWindow::dataPages() const {
    // The gates of users and PLC: nothing to compare where the protocol lacks them.
    return {m_cams, m_deadTimes, m_settings, m_pages.at(Users), m_pages.at(Plc)};
}

void MainWindow::createMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&New project…"), this, &MainWindow::newProject);
    file->addAction(tr("&Open project…"), QKeySequence::Open, this, &MainWindow::openProject);
    file->addAction(tr("&Save project"), QKeySequence::Save, this, &MainWindow::saveProject);
    file->addAction(tr("Save project &as…"), QKeySequence::SaveAs, this, &MainWindow::saveProjectAs);
    file->addSeparator();
    file->addAction(tr("Commissioning &report (PDF)…"), this, &MainWindow::exportReportInteractive);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    CamEditorWidget* editor = m_cams->editor();
    editor->undoAction()->setShortcut(QKeySequence::Undo);
    editor->redoAction()->setShortcut(QKeySequence::Redo);
    edit->addAction(editor->undoAction());
    edit->addAction(editor->redoAction());
    edit->addSeparator();
    edit->addActions(editor->editorActions());

    QMenu* device = menuBar()->addMenu(tr("&Device"));
    device->addAction(tr("&Connect"), this, [this] {
        m_session->connectTo(m_connection->connectionSettings(), m_connection->protocolSettings());
    });
    device->addAction(tr("&Disconnect"), m_session, &DeviceSession::disconnectFromDevice);
    device->addAction(tr("&Read everything"), this, [this] { readEverything(m_cams->editor()->currentProgram()); });
    device->addSeparator();
    device->addAction(tr("Co&mpare with device…"), this, &MainWindow::openCompare);
    device->addAction(tr("&Backup and restore…"), this, &MainWindow::openBackupWizard);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    QAction* dark = view->addAction(tr("&Dark palette"));
    dark->setCheckable(true);
    dark->setChecked(isDarkTheme());
    connect(dark, &QAction::toggled, this, [this](bool on) {
        applyTheme(on);
        Q_EMIT darkRequested(on);
    });
    QMenu* language = view->addMenu(tr("&Language"));
    auto* group = new QActionGroup(language);
    const QList<QPair<QString, QString>> languages{{QStringLiteral("en"), QStringLiteral("English")},
                                                   {QStringLiteral("de"), QStringLiteral("Deutsch")}};
    for (const auto& [code, name] : languages) {
        QAction* action = language->addAction(name);
        action->setCheckable(true);
        action->setChecked(currentLanguage() == code);
        group->addAction(action);
        const QString lang = code;
        connect(action, &QAction::triggered, this, [this, lang] { Q_EMIT languageRequested(lang); });
    }
    for (int i = 0; i < m_pages.size(); ++i) {
        view->addAction(m_pages[i]->sectionTitle(), this, [this, i] { showSection(Section(i)); });
    }

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About CamBench"), this, [this] {
        QMessageBox::about(this, tr("About CamBench"),
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
    statusBar()->addPermanentWidget(m_connectionLabel);
    comm::CommWorker& worker = m_session->worker();
    connect(&worker, &comm::CommWorker::jobStarted, this, [this](quint64, const QString& title) {
        if (title == MonitorPage::tr("Monitor")) return;  // polls would make the bar flicker
        m_jobLabel->setText(title);
        m_jobProgress->setRange(0, 0);
        m_jobProgress->show();
    });
    connect(&worker, &comm::CommWorker::jobProgress, this,
            [this](quint64, qint64 done, qint64 total, const QString&) {
                if (total <= 0) return;
                m_jobProgress->setRange(0, 1000);
                m_jobProgress->setValue(int(done * 1000 / total));
            });
    connect(&worker, &comm::CommWorker::jobFinished, this, [this] {
        m_jobLabel->clear();
        m_jobProgress->hide();
    });
}

void MainWindow::showSection(Section section) { m_nav->setCurrentRow(section); }

MainWindow::Section MainWindow::currentSection() const { return Section(m_stack->currentIndex()); }

void MainWindow::showMessage(const QString& text) {
    m_lastMessage = text;
    statusBar()->showMessage(text, 15000);
}

void MainWindow::updateTitle() {
    const int changes = m_workspace->changedCount();
    QString where = m_projectPath.isEmpty() ? QString() : QFileInfo(m_projectPath).fileName();
    if (where.isEmpty()) {
        where = m_workspace->infoFromDevice()
                    ? tr("CamCon %1 (device %2)").arg(m_workspace->info().epromDate).arg(m_workspace->info().deviceNumber)
                    : tr("offline project");
    }
    QString title = tr("CamBench – %1").arg(where) + QStringLiteral("[*]");
    if (changes > 0) title += QLatin1Char(' ') + tr("[%n change(s) not written]", nullptr, changes);
    setWindowTitle(title);
    setWindowModified(changes > 0);
}

void MainWindow::updateConnection() {
    const comm::ConnectionState state = m_session->state();
    QString color = QStringLiteral("#808080");
    if (state == comm::ConnectionState::Connected) color = QStringLiteral("#2eaa40");
    if (state == comm::ConnectionState::Connecting) color = QStringLiteral("#d89a1e");
    if (state == comm::ConnectionState::Lost) color = QStringLiteral("#d0402e");
    m_connectionLabel->setText(QStringLiteral("<span style='color:%1'>●</span> %2")
                                   .arg(color, m_session->stateText().toHtmlEscaped()));
    m_connectionLabel->setToolTip(m_session->lastMessage());
    const bool lost = state == comm::ConnectionState::Lost || m_session->isRetrying();
    if (state == comm::ConnectionState::Lost) {
        m_lostText->setText(tr("The connection to %1 was lost: %2 CamBench retries by itself; your "
                               "edits are kept.")
                                .arg(m_session->connection().port, m_session->lastMessage()));
        showMessage(tr("Connection lost: %1").arg(m_session->lastMessage()));
    }
    m_lostBanner->setVisible(lost);
    if (state == comm::ConnectionState::Connected && m_pendingProgram >= 0) {
        const int program = m_pendingProgram;
        m_pendingProgram = -1;
        readEverything(program);
    }
    if (state == comm::ConnectionState::Disconnected && m_pendingProgram >= 0 && !m_session->lastMessage().isEmpty()) {
        m_pendingProgram = -1;
        showMessage(tr("Not connected: %1").arg(m_session->lastMessage()));
        Q_EMIT loaded(false);
    }
}

void MainWindow::connectAndLoad(int program) {
    m_pendingProgram = program;
    m_session->connectTo(m_connection->connectionSettings(), m_connection->protocolSettings());
}

void MainWindow::readEverything(int program) {
    showMessage(tr("Reading the device…"));
    m_session->run<DeviceInfo>(
        this, tr("Read device identity"),
        [](comm::CamConDevice& client, comm::JobContext&) { return client.readInfo(); },
        [this, program](Result<DeviceInfo> info) {
            if (!info) {
                showMessage(tr("The device did not identify itself: %1").arg(info.error().message));
                Q_EMIT loaded(false);
                return;
            }
            m_workspace->setInfo(info.value(), true);
            for (SectionPage* page : m_pages) page->deviceConnected();
            m_cams->editor()->setCurrentProgram(program);
            m_cams->readProgram(program, [this](const Status& status) { Q_EMIT loaded(status.ok()); });
        });
}

CompareDialog* MainWindow::openCompare() {
    auto* dialog = new CompareDialog(dataPages(), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &CompareDialog::writeFinished, this, [this](const WriteReport& report) {
        showMessage(tr("Write: %1").arg(report.summary()));
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

bool MainWindow::confirmClose() {
    const int changes = m_workspace->changedCount();
    if (changes == 0) return true;
    QMessageBox box(QMessageBox::Warning, tr("Unwritten changes"),
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
        return m_workspace->changedCount() == 0 || !m_projectPath.isEmpty();
    }
    return box.clickedButton() != cancel;
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (confirmClose()) {
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
                              tr("The current edits are not written or saved. Replace them?")) != QMessageBox::Yes)
        return;
    m_session->disconnectFromDevice();
    loadProjectIntoWorkspace(*m_workspace, emptyProject(dialog.capacities()));
    m_projectPath.clear();
    updateTitle();
    showSection(Cams);
}

void MainWindow::openProject() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open project"), QString(),
                                                      tr("CamBench projects (*.json)"));
    if (path.isEmpty()) return;
    const Result<Project> project = loadProject(path);
    if (!project) {
        QMessageBox::warning(this, tr("Open project"), project.error().message);
        return;
    }
    loadProjectIntoWorkspace(*m_workspace, project.value());
    m_projectPath = path;
    updateTitle();
    showMessage(tr("Project %1 opened. Its content is not on the device until you write it.").arg(path));
}

void MainWindow::saveProject() {
    if (m_projectPath.isEmpty()) {
        saveProjectAs();
    } else {
        saveProjectTo(m_projectPath);
    }
}

void MainWindow::saveProjectAs() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Save project"), m_projectPath,
                                                      tr("CamBench projects (*.json)"));
    if (!path.isEmpty()) saveProjectTo(path);
}

void MainWindow::saveProjectTo(const QString& path) {
    const Status saved = cambench::saveProject(path, projectFromWorkspace(*m_workspace));
    if (!saved) {
        QMessageBox::warning(this, tr("Save project"), saved.error().message);
        return;
    }
    m_projectPath = path;
    updateTitle();
    showMessage(tr("Project saved to %1.").arg(path));
}

Status MainWindow::exportReport(const QString& path) { return CommissioningReport::write(path, *m_workspace); }

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
