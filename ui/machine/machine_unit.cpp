#include "machine_unit.h"

#include "machine_connection.h"

#include "ui/connection_page.h"
#include "ui/device_session.h"
#include "ui/family_gui.h"
#include "ui/main_window.h"
#include "ui/motion_stop.h"

namespace cambench {

MachineUnit::MachineUnit(MachineDevice device, StopControl* machineStop, QObject* parent)
    : QObject(parent),
      m_device(std::move(device)),
      m_machineStop(machineStop),
      m_session(new DeviceSession(this)),
      m_families(createFamilyGuis(m_session, this)) {
    connect(m_session, &DeviceSession::stateChanged, this, [this](comm::ConnectionState state) {
        // The machine file holds what the device is reached with: also a
        // port or protocol chosen on its Connection page.
        // The items that change by themselves are the file's, not the
        // connection's: they stay.
        if (state == comm::ConnectionState::Connected) {
            const QStringList volatileItems = m_device.volatileItems;
            m_device =
                machineDeviceFor(m_device.name, m_session->connection(), m_session->protocol());
            m_device.volatileItems = volatileItems;
        }
        Q_EMIT changed();
    });
    connect(m_session, &DeviceSession::deviceCheckedChanged, this, &MachineUnit::changed);
    connect(m_session->motionStop(), &MotionStop::motionChanged, this, &MachineUnit::changed);
    for (FamilyGui* family : m_families) {
        connect(family, &FamilyGui::titleChanged, this, &MachineUnit::changed);
        connect(family, &FamilyGui::identityChanged, this, &MachineUnit::changed);
    }
}

MachineUnit::~MachineUnit() {
    // Its pages point at this unit's session and families.
    delete m_window;
}

MainWindow* MachineUnit::window() const {
    return m_window;
}

MainWindow* MachineUnit::createWindow() {
    delete m_window;
    m_window = new MainWindow(m_session, m_families, m_machineStop);
    // A part of the machine's window, not a window of its own.
    m_window->setWindowFlags(Qt::Widget);
    connect(m_window, &MainWindow::languageRequested, this, &MachineUnit::languageRequested,
            Qt::QueuedConnection);
    return m_window;
}

void MachineUnit::connectDevice() {
    if (!m_window) createWindow();
    // A device added to the machine: its Connection page says how.
    if (m_device.option(QStringLiteral("port")).isEmpty()) return;
    const Result<MachineConnection> connection = machineConnection(m_device);
    if (!connection) {
        m_problem = connection.error().message;
        Q_EMIT changed();
        return;
    }
    m_problem.clear();
    m_window->connectionPage()->showConnection(connection->connection, *connection->protocol);
    m_window->connectAndLoad();
}

MachineUnit::Lamp MachineUnit::lamp() const {
    if (!m_problem.isEmpty()) return Lamp::Gone;
    switch (m_session->state()) {
        case comm::ConnectionState::Connected:
            return m_session->motionStop()->motion() == MotionStop::Motion::Moving
                       ? Lamp::Moving
                       : Lamp::Connected;
        case comm::ConnectionState::Connecting:
            return m_session->isRetrying() ? Lamp::Gone : Lamp::Connecting;
        case comm::ConnectionState::Lost:
            return Lamp::Gone;
        case comm::ConnectionState::Disconnected:
            return m_session->isRetrying() || !m_session->lastMessage().isEmpty() ? Lamp::Gone
                                                                                  : Lamp::Offline;
    }
    return Lamp::Offline;
}

QString MachineUnit::stateText() const {
    if (!m_problem.isEmpty()) return tr("not opened: %1").arg(m_problem);
    switch (lamp()) {
        case Lamp::Connected:
        case Lamp::Moving: {
            if (!m_session->deviceChecked()) return tr("connected, identifying…");
            const QString motion = m_session->motionStop()->motionText();
            return motion.isEmpty() ? tr("connected") : tr("connected, %1").arg(motion);
        }
        case Lamp::Connecting:
            return tr("connecting…");
        case Lamp::Gone:
            if (m_session->isRetrying() || m_session->state() == comm::ConnectionState::Lost)
                return tr("gone, retrying: %1").arg(m_session->lastMessage());
            return tr("not connected: %1").arg(m_session->lastMessage());
        case Lamp::Offline:
            break;
    }
    if (m_device.option(QStringLiteral("port")).isEmpty())
        return tr("not connected yet: choose its port on its Connection page");
    return tr("offline");
}

int MachineUnit::unwrittenCount() const {
    int count = 0;
    for (const FamilyGui* family : m_families) count += family->unwrittenCount();
    return count;
}

}  // namespace cambench
