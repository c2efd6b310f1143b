#include "device_session.h"

#include "motion_stop.h"
#include "shell_log.h"

#include <utility>

#include "comm/device/protocol_registry.h"

namespace cambench {

DeviceSession::DeviceSession(QObject* parent)
    : QObject(parent),
      m_worker(comm::makeCommWorker()),
      m_protocol(comm::ProtocolRegistry::instance().all().value(0)
                     ? comm::ProtocolSettingsPtr(
                           comm::ProtocolRegistry::instance().all().value(0)->makeSettings())
                     : nullptr) {
    m_motionStop = new MotionStop(this);
    m_retry.setInterval(2000);
    connect(&m_retry, &QTimer::timeout, this, [this] {
        qCInfo(shellLog) << "retrying lost connection to" << m_connection.port;
        m_worker->connectTo(m_connection, m_protocol);
    });
    connect(m_worker.get(), &comm::JobRunner::connectionStateChanged, this,
            &DeviceSession::onStateChanged, Qt::QueuedConnection);
}

DeviceSession::~DeviceSession() {
    m_retry.stop();
}

void DeviceSession::setLeaveCheck(QObject* owner, LeaveCheck check) {
    m_leaveOwner = owner;
    m_leaveCheck = std::move(check);
}

bool DeviceSession::mayLeaveDevice(const QString& action) {
    // Only a device on the line can say what moves, and be stopped.
    if (!m_leaveOwner || !m_leaveCheck || !m_motionStop->armed()) return true;
    return m_leaveCheck(action);
}

void DeviceSession::connectTo(const comm::ConnectionSettings& connection,
                              const comm::ProtocolSettingsPtr& protocol) {
    if (!mayLeaveDevice(tr("Connect to %1").arg(connection.port))) return;
    m_connection = connection;
    m_protocol = protocol;
    m_freshness.reset();
    m_wasLost = false;  // a connect asked for is no re-establishment
    m_reestablishing = false;
    reconnect();
}

void DeviceSession::reconnect() {
    m_wantConnected = true;
    m_worker->cancelAll();
    m_worker->connectTo(m_connection, m_protocol);
    // From now on the line may reach another device: nothing may show the
    // last one's identity as this port's until the worker has connected
    // and the device has identified itself.
    onStateChanged(comm::ConnectionState::Connecting, m_connection.port);
}

bool DeviceSession::disconnectFromDevice() {
    if (!mayLeaveDevice(tr("Disconnect"))) return false;
    m_wantConnected = false;
    m_wasLost = false;
    m_reestablishing = false;
    m_retry.stop();
    m_worker->cancelAll();
    m_worker->disconnectFromDevice();
    m_freshness.paused();
    return true;
}

void DeviceSession::setDevice(int device) {
    const bool another = m_protocol->device() != device;
    std::unique_ptr<comm::ProtocolSettings> changed = m_protocol->clone();
    changed->setDevice(device);
    m_protocol = std::move(changed);
    m_worker->setLinkDevice(device);
    if (!another) return;  // the same device addressed again (after a line backup)
    // Another device: what the last one answered (or did not) says nothing of it.
    m_freshness.reset();
    setDeviceChecked(false);
    Q_EMIT targetChanged();
}

void DeviceSession::setDeviceChecked(bool checked) {
    const bool other = std::exchange(m_anotherDevice, false);
    if (checked) setIdentifyFailed({});
    if (m_deviceChecked == checked) return;
    m_deviceChecked = checked;
    Q_EMIT deviceCheckedChanged(checked);
    if (checked && std::exchange(m_reestablishing, false)) Q_EMIT reestablished(!other);
}

void DeviceSession::setIdentifyFailed(const QString& why) {
    if (m_identifyProblem == why) return;
    m_identifyProblem = why;
    Q_EMIT identifyProblemChanged();
}

QString DeviceSession::stateText() const {
    switch (m_state) {
        case comm::ConnectionState::Disconnected:
            return m_retry.isActive() ? tr("Connection to %1 lost, retrying").arg(m_connection.port)
                                      : tr("Offline");
        case comm::ConnectionState::Connecting:
            return tr("Connecting to %1…").arg(m_connection.port);
        case comm::ConnectionState::Connected: {
            // "Connected" only for a device that identified itself.
            const bool simulated = m_connection.port == QLatin1String("sim") ||
                                   m_connection.port.startsWith(QLatin1String("sim:"));
            if (!m_identifyProblem.isEmpty())
                return simulated ? tr("No device identifies itself on the simulated line")
                                 : tr("No device identifies itself on %1").arg(m_connection.port);
            if (!m_deviceChecked)
                return simulated
                           ? tr("Checking which device answers on the simulated line…")
                           : tr("Checking which device answers on %1…").arg(m_connection.port);
            return simulated ? tr("Connected to the simulated device")
                             : tr("Connected to %1").arg(m_connection.port);
        }
        case comm::ConnectionState::Lost:
            return tr("Connection to %1 lost, retrying").arg(m_connection.port);
    }
    return {};
}

void DeviceSession::onStateChanged(comm::ConnectionState state, const QString& message) {
    m_state = state;
    m_message = message;
    qCInfo(shellLog) << "connection state" << int(state) << message;
    // Every connect may reach another device: it is identified again.
    setDeviceChecked(false);
    setIdentifyFailed({});
    switch (state) {
        case comm::ConnectionState::Lost:
            m_wasLost = true;
            m_freshness.missed();
            if (m_wantConnected && !m_retry.isActive()) m_retry.start();
            break;
        case comm::ConnectionState::Connected:
            m_retry.stop();
            break;
        case comm::ConnectionState::Disconnected:
            // A failed retry ends here too; keep trying while the user wants the line.
            if (m_wasLost && m_wantConnected && !m_retry.isActive()) m_retry.start();
            break;
        case comm::ConnectionState::Connecting:
            break;
    }
    Q_EMIT stateChanged(state, message);
    if (state == comm::ConnectionState::Connected && m_wasLost) {
        m_wasLost = false;
        m_reestablishing = true;
        Q_EMIT reconnected();
    }
}

}  // namespace cambench
