#include "main_window.h"

#include "check_report_dialog.h"
#include "connection_page.h"
#include "connection_status.h"
#include "device_session.h"
#include "family_gui.h"
#include "gui_settings.h"
#include "language.h"
#include "last_write_report.h"
#include "motion_leave_question.h"
#include "motion_stop.h"
#include "program_stop.h"
#include "report_dialog.h"
#include "sentence.h"
#include "stop_bar.h"
#include "stop_shortcut.h"
#include "theme.h"

#include "comm/device/family_registry.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QFileInfo>
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
#include <QToolButton>

namespace cambench {

MainWindow::MainWindow(DeviceSession* session, const QList<FamilyGui*>& families,
                       StopControl* machineStop, QWidget* parent)
    : QMainWindow(parent),
      m_session(session),
      m_nav(new QListWidget),
      m_stack(new QStackedWidget),
      m_strip(new ConnectionStrip(session)),
      m_indicator(new ConnectionIndicator(session)),
      m_stopBar(new StopBar(machineStop ? machineStop : session->motionStop(),
                            StopShortcut::key().toString(QKeySequence::NativeText))),
      m_jobLabel(new QLabel),
      m_jobProgress(new QProgressBar),
      m_jobCancel(new QToolButton),
      m_lastWrite(new QToolButton),
      m_inMachine(machineStop != nullptr) {
    createPages(families);
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
    // STOP above every page while the device can move something; its key
    // works from every widget of the window.
    layout->addWidget(m_stopBar);
    if (m_inMachine)
        m_stopBar->button()->setToolTip(
            tr("Stops every axis and drive of every device of the machine, without a question. "
               "%1 does the same from every page.")
                .arg(StopShortcut::key().toString(QKeySequence::NativeText)));
    else
        ProgramStop::instance().add(session->motionStop());  // Escape and every dialog's STOP
    layout->addLayout(body, 1);
    setCentralWidget(central);

    // The strip names the connected device as its family knows it.
    m_strip->setIdentity([this]() -> QString {
        const FamilyWindow* family = sessionWindow();
        return family ? family->gui()->identityLine() : QString();
    });
    for (FamilyGui* family : families) {
        connect(family, &FamilyGui::identityChanged, m_strip, &ConnectionStrip::update);
        // The title names the device too (windowSubject()).
        connect(family, &FamilyGui::identityChanged, this, &MainWindow::updateTitle);
        connect(family, &FamilyGui::titleChanged, this, &MainWindow::updateTitle);
    }
    connect(m_nav, &QListWidget::currentRowChanged, m_stack, &QStackedWidget::setCurrentIndex);
    connect(m_nav, &QListWidget::currentRowChanged, this, &MainWindow::updateLivePolling);
    connect(m_session, &DeviceSession::stateChanged, this, &MainWindow::updateConnection);
    connect(m_session, &DeviceSession::targetChanged, this, [this] {
        if (m_session->isOnline()) checkDevice();
    });
    // Said only once the device answered and identified itself.
    connect(m_session, &DeviceSession::reestablished, this, [this](bool sameDevice) {
        showMessage(sameDevice ? tr("Connection re-established: the same device answers. Your "
                                    "edits are unchanged; Compare with device reads what the "
                                    "device holds now.")
                               : tr("Connection re-established, but another device answers on "
                                    "this port: see the note at the top."));
    });
    // Quitting is asked in closeEvent; a connect or disconnect asks here.
    m_session->setLeaveCheck(this, [this](const QString& action) {
        return askBeforeLeavingMotion(this, *m_session->motionStop(), action);
    });
    m_nav->setCurrentRow(Connection);
    updateConnection();
    updateTitle();
    resize(1280, 800);
    updateLivePolling();
}

MainWindow::~MainWindow() = default;

void MainWindow::createPages(const QList<FamilyGui*>& families) {
    m_connection = new ConnectionPage(m_session);
    addPage(m_connection, {});
    for (FamilyGui* family : families) {
        FamilyWindow* part = family->createWindow(this);
        m_families << part;
        for (SectionPage* page : part->pages()) addPage(page, family->familyId());
        m_connection->addIdentityPanel(family->familyId(), part->identityPanel());
    }
    connect(m_connection, &ConnectionPage::deviceSelected, this, [this] { readAtStart(); });
    showFamilyPages();
}

void MainWindow::addPage(SectionPage* page, const QString& familyId) {
    m_pages << page;
    m_pageFamilies << familyId;
    m_stack->addWidget(page);
    m_nav->addItem(page->sectionTitle());
    page->setNavItem(m_nav->item(m_nav->count() - 1));
    connect(page, &SectionPage::statusMessage, this, &MainWindow::showMessage);
}

FamilyWindow* MainWindow::familyWindow(const QString& familyId) const {
    for (FamilyWindow* family : m_families)
        if (family->gui()->familyId() == familyId) return family;
    return nullptr;
}

FamilyWindow* MainWindow::sessionWindow() const {
    return familyWindow(sessionFamily(*m_session));
}

void MainWindow::showFamilyPages() {
    const QString family = sessionFamily(*m_session);
    const auto foreign = [&family](const QString& owner) {
        return !owner.isEmpty() && owner != family;
    };
    for (int row = 0; row < m_pages.size(); ++row)
        m_nav->item(row)->setHidden(foreign(m_pageFamilies.at(row)));
    for (const auto& [action, owner] : m_familyActions) action->setVisible(!foreign(owner));
    if (m_nav->currentItem() && m_nav->currentItem()->isHidden()) showSection(Connection);
}

void MainWindow::createMenus() {
    // Each family adds its entries between the shell's; the entries a menu
    // gained from a family are that family's.
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QMenu* device = menuBar()->addMenu(tr("&Device"));
    QMenu* tools = menuBar()->addMenu(tr("&Tools"));
    device->addAction(tr("&Connect"), this, [this] {
        m_session->connectTo(m_connection->connectionSettings(), m_connection->protocolSettings());
    });
    device->addAction(tr("&Disconnect"), m_session, &DeviceSession::disconnectFromDevice);
    for (FamilyWindow* family : m_families) {
        QList<QAction*> before;
        for (QMenu* menu : {file, edit, device, tools}) before << menu->actions();
        family->addMenuEntries({file, edit, device, tools});
        for (QMenu* menu : {file, edit, device, tools}) {
            for (QAction* action : menu->actions())
                if (!before.contains(action))
                    m_familyActions.append({action, family->gui()->familyId()});
        }
    }
    if (!m_inMachine) addMachineEntries(file);
    file->addSeparator();
    // Inside a machine's window: quits that window (asking every device).
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, [this] { window()->close(); });
    device->addSeparator();
    QAction* lastWrite =
        device->addAction(tr("&Last write report…"), this, &MainWindow::showLastWriteReport);
    lastWrite->setEnabled(!m_session->lastWriteReport().isEmpty());
    connect(&m_session->lastWriteReport(), &LastWriteReport::changed, lastWrite,
            [lastWrite] { lastWrite->setEnabled(true); });

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
        QAction* show = view->addAction(title.replace(QLatin1Char('&'), QLatin1String("&&")), this,
                                        [this, i] { showSection(i); });
        if (!m_pageFamilies.at(i).isEmpty()) m_familyActions.append({show, m_pageFamilies.at(i)});
    }
    showFamilyPages();

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    // Reading only (issue 29): tries our provisional readings on the device.
    help->addAction(tr("&Check this device…"), this, [this] { runDeviceCheck(m_session, this); });
    help->addAction(tr("&About CamBench"), this, [this] {
        QStringList families;
        for (const comm::FamilyInfo* info : comm::FamilyRegistry::instance().all())
            if (info->built) families << info->title;
        QMessageBox::about(
            this, tr("About CamBench"),
            tr("<b>CamBench %1</b><p>Programming, monitoring and backup of "
               "machine controllers: %2.</p>")
                .arg(QStringLiteral(CAMBENCH_VERSION), families.join(QStringLiteral(", "))));
    });
}

void MainWindow::addMachineEntries(QMenu* file) {
    // The machine: several devices at once, each in its own connection.
    file->addSeparator();
    file->addAction(tr("Open &machine…"), this, &MainWindow::openMachineRequested);
    file->addAction(tr("New mac&hine…"), this, &MainWindow::newMachineRequested);
    file->addAction(tr("Open &demo machine"), this, &MainWindow::demoMachineRequested);
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
    connect(&m_session->lastWriteReport(), &LastWriteReport::changed, this,
            &MainWindow::updateLastWriteButton);
    updateLastWriteButton();
    comm::JobRunner& worker = m_session->worker();
    // The STOP reports in its bar; between two requests of a backup it
    // must not take the backup's place in the status bar.
    for (const QString& quiet : MotionStop::jobTitles()) addQuietJobTitle(quiet);
    m_jobCancel->setText(tr("Cancel"));
    m_jobCancel->setToolTip(tr("Cancel what the device is doing for you now."));
    m_jobCancel->hide();
    statusBar()->insertPermanentWidget(2, m_jobCancel);
    connect(m_jobCancel, &QToolButton::clicked, this, [this] {
        if (m_runningJob != 0) m_session->worker().cancel(m_runningJob);
    });
    connect(&worker, &comm::JobRunner::jobStarted, this, [this](quint64 id, const QString& title) {
        if (m_quietJobs.contains(title)) return;
        m_runningJob = id;
        m_jobLabel->setText(title);
        m_jobProgress->setRange(0, 0);
        m_jobProgress->show();
        m_jobCancel->show();
    });
    connect(&worker, &comm::JobRunner::jobProgress, this,
            [this](quint64 id, qint64 done, qint64 total, const QString&) {
                if (id != m_runningJob || total <= 0) return;
                m_jobProgress->setRange(0, 1000);
                m_jobProgress->setValue(int(done * 1000 / total));
            });
    connect(&worker, &comm::JobRunner::jobFinished, this, [this](quint64 id) {
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

void MainWindow::showSection(int section) {
    m_nav->setCurrentRow(section);
}

void MainWindow::showPage(SectionPage* page) {
    if (const int row = rowOf(page); row >= 0) showSection(row);
}

void MainWindow::updateLivePolling() {
    // Only pages that show live values keep the line busy with polls.
    SectionPage* shown = m_pages.value(currentSection());
    for (FamilyWindow* family : m_families) family->pageShown(shown);
}

int MainWindow::currentSection() const {
    return m_stack->currentIndex();
}

void MainWindow::updateLastWriteButton() {
    const LastWriteReport& report = m_session->lastWriteReport();
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
    const LastWriteReport& report = m_session->lastWriteReport();
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
    const FamilyWindow* family = sessionWindow();
    if (!family && !m_families.isEmpty()) family = m_families.first();
    const QString subject = family ? family->gui()->windowSubject() : QString();
    int changes = 0;
    for (const FamilyWindow* part : m_families) changes += part->gui()->unwrittenCount();
    QString title = (subject.isEmpty() ? tr("CamBench") : tr("CamBench – %1").arg(subject)) +
                    QStringLiteral("[*]");
    if (changes > 0) title += QLatin1Char(' ') + tr("[%n change(s) not written]", nullptr, changes);
    setWindowTitle(title);
    setWindowModified(changes > 0);
}

void MainWindow::updateConnection() {
    const comm::ConnectionState state = m_session->state();
    // A connect a person asked for may reach another device, of this
    // family or another: from now on no page and no title speaks of the
    // one before, also when nothing answers (a retry of a lost line keeps
    // the stale values).
    if (state == comm::ConnectionState::Connecting && !m_session->isRetrying())
        for (FamilyWindow* part : m_families) part->forgetDevice();
    if (state == comm::ConnectionState::Lost)
        showMessage(tr("Connection lost: %1").arg(asSentence(m_session->lastMessage())));
    showFamilyPages();
    updateTitle();
    m_strip->update();
    // Every connect and reconnect may reach another device.
    if (state == comm::ConnectionState::Connected) checkDevice();
    // A connect that failed (a user's disconnect carries no message).
    if (state == comm::ConnectionState::Disconnected && !m_session->lastMessage().isEmpty() &&
        !m_session->isRetrying()) {
        showMessage(tr("Not connected: %1").arg(m_session->lastMessage()));
        if (m_loadPending) reportLoaded(false);
    }
}

void MainWindow::connectAndLoad() {
    m_loadPending = true;
    m_session->connectTo(m_connection->connectionSettings(), m_connection->protocolSettings());
}

void MainWindow::readAtStart() {
    m_loadPending = true;
    if (m_session->isOnline()) checkDevice();
}

void MainWindow::reportLoaded(bool ok) {
    m_loadPending = false;
    Q_EMIT loaded(ok);
}

void MainWindow::checkDevice() {
    // One reset for every family, not only the one of the new device: the
    // pages of a family switched away from would otherwise keep what they
    // said of their last device ("STOP sent to every axis", a compared
    // file) until a device of theirs comes again.
    for (FamilyWindow* part : m_families) part->forgetDevice();
    FamilyWindow* family = sessionWindow();
    const bool load = std::exchange(m_loadPending, false);
    if (family) {
        family->deviceOnLine(load);
    } else if (load) {
        showMessage(tr("No page of CamBench knows the devices of this protocol."));
        reportLoaded(false);
    }
}

bool MainWindow::confirmClose() {
    if (!m_session->mayLeaveDevice(tr("Quit"))) return false;
    for (FamilyWindow* family : m_families)
        if (!family->confirmClose()) return false;
    return true;
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (confirmClose()) {
        // The layout remembered is the single device's window's.
        if (!m_inMachine) guisettings::saveWindow(*this, currentSection());
        event->accept();
    } else {
        event->ignore();
    }
}

}  // namespace cambench
