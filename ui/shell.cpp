#include "shell.h"

#include "connection_page.h"
#include "device_session.h"
#include "family_gui.h"
#include "gui_settings.h"
#include "language.h"
#include "machine/demo_machine.h"
#include "machine/machine.h"
#include "machine/machine_connection.h"
#include "machine/machine_window.h"
#include "main_window.h"
#include "window_fit.h"

#include "comm/device/protocol_registry.h"

#include <QApplication>
#include <QFileDialog>
#include <QInputDialog>
#include <QMessageBox>

namespace cambench {

Shell::Shell(QObject* parent)
    : QObject(parent),
      m_session(new DeviceSession(this)),
      m_families(createFamilyGuis(m_session, this)) {
    // Only a connection that worked is worth remembering for the next start.
    connect(m_session, &DeviceSession::stateChanged, this, [this](comm::ConnectionState state) {
        if (state == comm::ConnectionState::Connected)
            guisettings::saveConnection(m_session->connection(), m_session->protocol());
    });
}

Shell::~Shell() {
    for (Machine* machine : machines()) delete machine;
    delete m_window;
}

FamilyGui* Shell::family(const QString& familyId) const {
    for (FamilyGui* family : m_families)
        if (family->familyId() == familyId) return family;
    return nullptr;
}

MainWindow* Shell::createWindow() {
    auto* window = new MainWindow(m_session, m_families);
    connect(window, &MainWindow::languageRequested, this, &Shell::switchLanguage,
            Qt::QueuedConnection);
    connect(window, &MainWindow::openMachineRequested, this, &Shell::askForMachineFile);
    connect(window, &MainWindow::newMachineRequested, this, &Shell::newMachine);
    connect(window, &MainWindow::demoMachineRequested, this, &Shell::openDemoMachine);
    return window;
}

void Shell::start(const QString& port, const QString& protocol) {
    m_window = createWindow();
    const int section = guisettings::restoreWindow(*m_window);
    if (section >= 0 && section < m_window->sectionCount()) m_window->showSection(section);
    showFitting(*m_window, section >= 0);
    if (port.isEmpty()) {
        // The last connection that worked, with its protocol and settings.
        const auto remembered = guisettings::loadConnection();
        if (!remembered) return;
        m_window->connectionPage()->showConnection(remembered->connection, *remembered->protocol);
    } else {
        m_window->connectionPage()->setPort(port);
        if (!protocol.isEmpty()) m_window->connectionPage()->setProtocol(protocol);
    }
    m_window->connectAndLoad();
}

void Shell::switchLanguage(const QString& language) {
    setLanguage(language);
    guisettings::setLanguage(currentLanguage());
    // The window the switch was asked in stays in front.
    Machine* inFront = nullptr;
    for (Machine* machine : machines()) {
        if (QApplication::activeWindow() == static_cast<QWidget*>(machine->window()))
            inFront = machine;
        machine->rebuildWindow();
    }
    const auto raiseMachine = [inFront] {
        if (!inFront) return;
        inFront->window()->raise();
        inFront->window()->activateWindow();
    };
    if (!m_window) return raiseMachine();
    MainWindow* old = m_window;
    MainWindow* window = createWindow();
    window->setGeometry(old->geometry());
    window->showSection(old->currentSection());
    m_window = window;
    window->show();
    // Deleted now, not later: its pages point at this shell's session, and
    // the shell may be gone before a deferred delete would run. The switch
    // arrives through a queued call, never from inside the old window.
    delete old;
    raiseMachine();
    Q_EMIT windowRebuilt(window);
}

QList<Machine*> Shell::machines() const {
    QList<Machine*> open;
    for (const QPointer<Machine>& machine : m_machines)
        if (machine) open << machine;
    return open;
}

Machine* Shell::openMachine(const MachineFile& file, const QString& path) {
    auto* machine = new Machine(file, path, this);
    m_machines << machine;
    connect(machine, &Machine::languageRequested, this, &Shell::switchLanguage,
            Qt::QueuedConnection);
    // Closed after every device was asked: its lines and workers go with it.
    connect(machine, &Machine::closed, machine, &QObject::deleteLater);
    machine->open();
    return machine;
}

Result<Machine*> Shell::openMachineFile(const QString& path) {
    const Result<MachineFile> file = readMachineFile(path);
    if (!file) return file.error();
    return openMachine(*file, path);
}

void Shell::askForMachineFile() {
    const QString path =
        QFileDialog::getOpenFileName(m_window, tr("Open machine"), {}, tr("Machine file (*.json)"));
    if (path.isEmpty()) return;
    const Result<Machine*> machine = openMachineFile(path);
    if (!machine) QMessageBox::warning(m_window, tr("Open machine"), machine.error().message);
}

void Shell::openDemoMachine() {
    const Result<MachineFile> file = demoMachineFile();
    if (!file) {
        QMessageBox::warning(m_window, tr("Open demo machine"), file.error().message);
        return;
    }
    openMachine(*file, {});
}

void Shell::newMachine() {
    const QString name =
        QInputDialog::getText(m_window, tr("New machine"), tr("Name of the machine:")).trimmed();
    if (name.isEmpty()) return;
    MachineFile file;
    file.machine = name;
    // The device of this window is the machine's first; the machine opens
    // its own line to it, so this window gives its line up first (a serial
    // port is opened once). Its edits stay in this window.
    if (m_session->wantsConnection()) {
        if (!m_session->disconnectFromDevice()) return;
        const comm::ProtocolInfo* info =
            comm::ProtocolRegistry::instance().find(m_session->protocol().protocolId());
        file.devices << machineDeviceFor(info ? info->familyId : QStringLiteral("device"),
                                         m_session->connection(), m_session->protocol());
    }
    Machine* machine = openMachine(file, {});
    if (file.devices.isEmpty())
        machine->window()->showMessage(tr("Add the machine's devices: Machine → Add device…"));
}

}  // namespace cambench
