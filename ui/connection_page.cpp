#include "connection_page.h"

#include "device_session.h"
#include "sentence.h"
#include "workspace.h"

#include "ui/protocols/protocol_settings_widget.h"

#include "comm/device/protocol_registry.h"
#include "comm/transport/serial_port_list.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QLocale>
#include <QPushButton>
#include <QToolButton>

namespace cambench {

namespace {
const QString kSimPort = QStringLiteral("sim");
}

ConnectionPage::ConnectionPage(DeviceSession* session, Workspace* workspace, QWidget* parent)
    : SectionPage(parent), m_session(session), m_workspace(workspace) {
    auto* line = new QGroupBox(tr("Line"));
    auto* form = new QFormLayout(line);
    m_simNote = new QLabel(
        tr("You are working on the simulated demo device: no machine is attached, and nothing "
           "you write here reaches a real CamCon. To work on a machine, choose its port below "
           "(or type it: /dev/ttyUSB0, COM3, tcp://host:port), the protocol and the baud rate, "
           "then press Connect."));
    m_simNote->setWordWrap(true);
    m_simNote->setObjectName(QStringLiteral("simulatedNote"));
    m_simNote->hide();
    form->addRow(m_simNote);

    m_port = new QComboBox;
    m_port->setEditable(true);
    // Typed text is the port (a pty, tcp://host:port, a port the list lacks):
    // Enter must not turn it into an entry without port data.
    m_port->setInsertPolicy(QComboBox::NoInsert);
    m_port->setToolTip(
        tr("A serial port, tcp://host:port for a serial device server, or the "
           "simulated device."));
    auto* refresh = new QToolButton;
    refresh->setText(tr("Refresh"));
    refresh->setToolTip(tr("Look for serial ports again"));
    auto* portRow = new QHBoxLayout;
    portRow->addWidget(m_port, 1);
    portRow->addWidget(refresh);
    form->addRow(tr("Port:"), portRow);

    m_protocol = new QComboBox;
    for (const comm::ProtocolInfo* info : comm::ProtocolRegistry::instance().all())
        m_protocol->addItem(protocolTitle(*info), info->id);
    form->addRow(tr("Protocol:"), m_protocol);

    m_baud = new QComboBox;
    for (int baud : {9600, 19200, 38400, 57600, 115200})
        m_baud->addItem(QString::number(baud), baud);
    form->addRow(tr("Baud rate:"), m_baud);

    m_protocolBox = new QVBoxLayout;
    form->addRow(m_protocolBox);

    m_connect = new QPushButton(tr("Connect"));
    m_disconnect = new QPushButton(tr("Disconnect"));
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_connect);
    buttons->addWidget(m_disconnect);
    buttons->addStretch();
    form->addRow(buttons);
    m_failure = new QLabel;
    m_failure->setWordWrap(true);
    m_failure->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_failure->setObjectName(QStringLiteral("connectFailure"));
    m_failure->hide();
    form->addRow(m_failure);

    auto* bus = new QGroupBox(tr("Devices on the line"));
    auto* busLayout = new QVBoxLayout(bus);
    m_scan = new QPushButton(tr("Scan bus"));
    m_scan->setToolTip(
        tr("Ask every device number 0–63 for an answer (Multiuser), or identify "
           "the one device of a point-to-point line."));
    m_devices = new QListWidget;
    m_devices->setToolTip(tr("Double-click a device to work with it."));
    busLayout->addWidget(m_scan, 0, Qt::AlignLeft);
    busLayout->addWidget(m_devices);

    auto* identity = new QGroupBox(tr("Device"));
    m_identity = identity;
    m_info = new QFormLayout(identity);

    auto* left = new QVBoxLayout;
    left->addWidget(line);
    left->addWidget(bus, 1);
    auto* layout = new QHBoxLayout(this);
    layout->addLayout(left, 3);
    layout->addWidget(identity, 2);

    fillPorts();
    showProtocolWidget();
    // A rebuilt window (language switch) shows the line in use.
    if (m_session->state() != comm::ConnectionState::Disconnected || m_session->isRetrying())
        showConnection(m_session->connection(), m_session->protocol());
    connect(refresh, &QToolButton::clicked, this, &ConnectionPage::fillPorts);
    connect(m_protocol, &QComboBox::currentIndexChanged, this, [this] {
        if (const comm::ProtocolInfo* info = currentProtocol())
            m_baud->setCurrentText(QString::number(info->defaultSerial.baud));
        showProtocolWidget();
        updateButtons();
    });
    connect(m_connect, &QPushButton::clicked, this,
            [this] { m_session->connectTo(connectionSettings(), protocolSettings()); });
    connect(m_disconnect, &QPushButton::clicked, m_session, &DeviceSession::disconnectFromDevice);
    connect(m_scan, &QPushButton::clicked, this, &ConnectionPage::scanBus);
    connect(m_devices, &QListWidget::itemActivated, this, [this](QListWidgetItem* item) {
        const int device = item->data(Qt::UserRole).toInt();
        if (const comm::ProtocolInfo* info = currentProtocol(); info && m_protocolWidget) {
            std::unique_ptr<comm::ProtocolSettings> settings = info->makeSettings();
            m_protocolWidget->store(*settings);
            settings->setDevice(device);
            m_protocolWidget->load(*settings);
        }
        m_session->setDevice(device);
        Q_EMIT deviceSelected(device);
    });
    connect(m_session, &DeviceSession::stateChanged, this, &ConnectionPage::updateButtons);
    connect(m_session, &DeviceSession::stateChanged, this, &ConnectionPage::showInfo);
    connect(m_session, &DeviceSession::stateChanged, this, &ConnectionPage::showConnectFailure);
    connect(m_session, &DeviceSession::stateChanged, this, &ConnectionPage::showSimulatedNote);
    connect(m_session, &DeviceSession::deviceCheckedChanged, this, &ConnectionPage::showInfo);
    connect(m_workspace, &Workspace::infoChanged, this, &ConnectionPage::showInfo);
    updateButtons();
    showInfo();
    showSimulatedNote();
}

void ConnectionPage::fillPorts() {
    const QString current = connectionSettings().port;
    m_port->clear();
    m_port->addItem(tr("Simulated device"), kSimPort);
    // With the adapter's description, maker, serial number and USB ids: the
    // right one of several adapters is easy to pick.
    for (const comm::SerialPortEntry& port : comm::availableSerialPorts()) {
        m_port->addItem(port.label(), port.location);
        m_port->setItemData(m_port->count() - 1, port.label(), Qt::ToolTipRole);
    }
    setPort(current.isEmpty() ? kSimPort : current);
}

void ConnectionPage::setPort(const QString& port) {
    const int index = m_port->findData(port);
    if (index >= 0) {
        m_port->setCurrentIndex(index);
    } else {
        m_port->setEditText(port);
    }
}

void ConnectionPage::showConnection(const comm::ConnectionSettings& connection,
                                    const comm::ProtocolSettings& protocol) {
    setPort(connection.port);
    setProtocol(protocol.protocolId());
    m_baud->setCurrentText(QString::number(connection.serial.baud));
    // Also called before the protocol box's signal is connected: put up
    // this protocol's widget here, then let it show the numbers.
    showProtocolWidget();
    if (m_protocolWidget) m_protocolWidget->load(protocol);
}

void ConnectionPage::setProtocol(const QString& id) {
    const int index = m_protocol->findData(id);
    if (index >= 0) m_protocol->setCurrentIndex(index);
}

const comm::ProtocolInfo* ConnectionPage::currentProtocol() const {
    return comm::ProtocolRegistry::instance().find(m_protocol->currentData().toString());
}

QString ConnectionPage::protocolTitle(const comm::ProtocolInfo& info) {
    if (info.id == QLatin1String("standard")) return tr("Standard (point to point)");
    if (info.id == QLatin1String("multiuser")) return tr("Multiuser (RS485 bus)");
    if (info.id == QLatin1String("3964r-n96")) return tr("Table interface, 3964R n96 (9600 8N1)");
    if (info.id == QLatin1String("3964r-e38")) return tr("Table interface, 3964R e38 (38400 8E1)");
    return info.title;
}

comm::ConnectionSettings ConnectionPage::connectionSettings() const {
    comm::ConnectionSettings settings;
    const int index = m_port->currentIndex();
    // An entry from the list carries its port in the data; typed text is the port.
    const bool listed = index >= 0 && m_port->itemText(index) == m_port->currentText() &&
                        !m_port->itemData(index).toString().isEmpty();
    settings.port = listed ? m_port->itemData(index).toString() : m_port->currentText().trimmed();
    if (const comm::ProtocolInfo* info = currentProtocol()) {
        settings.serial = info->defaultSerial;
        settings.protocol = info->id;
    }
    settings.serial.baud = m_baud->currentData().toInt();
    return settings;
}

comm::ProtocolSettingsPtr ConnectionPage::protocolSettings() const {
    const comm::ProtocolInfo* info = currentProtocol();
    if (!info) return m_session->protocolSettings();
    std::unique_ptr<comm::ProtocolSettings> settings = info->makeSettings();
    if (m_protocolWidget) m_protocolWidget->store(*settings);
    return comm::ProtocolSettingsPtr(std::move(settings));
}

void ConnectionPage::showProtocolWidget() {
    delete m_protocolWidget;
    const comm::ProtocolInfo* info = currentProtocol();
    m_protocolWidget = info ? ProtocolWidgetRegistry::instance().create(info->id) : nullptr;
    if (!m_protocolWidget) return;
    m_protocolBox->addWidget(m_protocolWidget);
    connect(m_protocolWidget, &ProtocolSettingsWidget::protocolRequested, this,
            &ConnectionPage::setProtocol, Qt::QueuedConnection);
}

void ConnectionPage::updateButtons() {
    const auto state = m_session->state();
    const bool idle = state == comm::ConnectionState::Disconnected;
    m_connect->setEnabled(state != comm::ConnectionState::Connecting);
    m_connect->setText(idle ? tr("Connect") : tr("Reconnect"));
    m_disconnect->setEnabled(!idle);
    m_scan->setEnabled(m_session->isOnline());
}

void ConnectionPage::scanBus() {
    m_devices->clear();
    m_scan->setEnabled(false);
    Q_EMIT statusMessage(tr("Scanning the bus…"));
    const comm::ProtocolInfo* info =
        comm::ProtocolRegistry::instance().find(m_session->protocol().protocolId());
    if (!info || !info->isBus) {
        // A point-to-point line has exactly one device: identify it.
        m_session->run<QList<int>>(
            this, tr("Identify device"),
            [](comm::CamConDevice& client, comm::JobContext&) -> Result<QList<int>> {
                const auto info = client.readInfo();
                if (!info) return info.error();
                return QList<int>{info->deviceNumber};
            },
            [this](Result<QList<int>> devices) { showScanResult(devices); });
        return;
    }
    m_session->run<QList<int>>(
        this, tr("Scan bus"),
        [](comm::CamConDevice& device, comm::JobContext& job) -> Result<QList<int>> {
            if (!device.has(comm::CamConCapability::BusScan))
                return device.missing(comm::CamConCapability::BusScan);
            return device.scanBus(0, 63,
                                  [&job](qint64 done, qint64 total) { job.progress(done, total); });
        },
        [this](Result<QList<int>> devices) { showScanResult(devices); });
}

void ConnectionPage::showScanResult(const Result<QList<int>>& devices) {
    updateButtons();
    if (!devices) {
        Q_EMIT statusMessage(tr("Bus scan failed: %1").arg(devices.error().message));
        return;
    }
    for (int device : devices.value()) {
        auto* item = new QListWidgetItem(tr("CamCon, device number %1").arg(device));
        item->setData(Qt::UserRole, device);
        m_devices->addItem(item);
    }
    Q_EMIT statusMessage(tr("%n device(s) found", nullptr, int(devices->size())));
}

void ConnectionPage::showSimulatedNote() {
    const QString port = m_session->connection().port;
    const bool simulated = port == kSimPort || port.startsWith(kSimPort + QLatin1Char(':'));
    m_simNote->setVisible(simulated && m_session->state() != comm::ConnectionState::Disconnected);
}

void ConnectionPage::showConnectFailure() {
    const comm::ConnectionState state = m_session->state();
    if (state == comm::ConnectionState::Connecting || state == comm::ConnectionState::Connected) {
        m_failure->hide();
        return;
    }
    if (state != comm::ConnectionState::Disconnected || m_session->lastMessage().isEmpty()) return;
    const QString port = m_session->connection().port;
    m_failure->setText(withoutCommandNames(
        tr("Not connected to %1: %2\nCheck the port name (a serial port, tcp://host:port for a "
           "device server), the protocol and baud rate, the cable and the device's power, then "
           "press Connect again.")
            .arg(port.isEmpty() ? tr("(no port given)") : port,
                 asSentence(m_session->lastMessage()))));
    QPalette alarm = m_failure->palette();
    alarm.setColor(QPalette::WindowText, QColor(0xd0, 0x30, 0x20));
    m_failure->setPalette(alarm);
    m_failure->show();
}

void ConnectionPage::showInfo() {
    while (m_info->rowCount() > 0) m_info->removeRow(0);
    const DeviceInfo& info = m_workspace->info();
    const bool checked = m_session->isOnline() && m_session->deviceChecked();
    // Offline (or not yet identified), the identity is the last device's,
    // not necessarily the one on the port chosen now: greyed, and said.
    m_identity->setEnabled(checked || !m_workspace->infoFromDevice());
    if (!m_workspace->infoFromDevice()) {
        m_info->addRow(new QLabel(tr("Not read from a device (offline project).")));
    } else if (!checked) {
        const QDateTime at =
            m_workspace->readTimes().parts.value(ProjectPart::Device).toLocalTime();
        auto* last = new QLabel(
            tr("Last connected: CamCon %1, device number %2, at %3. Not necessarily the device "
               "on the port chosen now.")
                .arg(info.epromDate)
                .arg(info.deviceNumber)
                .arg(QLocale().toString(at.time(), QLocale::ShortFormat)));
        last->setWordWrap(true);
        m_info->addRow(last);
    }
    const QString units = tr("%1 … %2");
    const auto row = [this](const QString& label, const QString& value) {
        auto* text = new QLabel(value);
        text->setTextInteractionFlags(Qt::TextSelectableByMouse);
        m_info->addRow(label, text);
    };
    if (m_workspace->infoFromDevice()) {
        row(tr("Firmware (EPROM date):"), info.epromDate);
        row(tr("Device number:"), QString::number(info.deviceNumber));
    }
    row(tr("Outputs:"), QString::number(info.outputs));
    row(tr("Inputs:"), QString::number(info.inputs));
    row(tr("Programs:"), tr("0 … %1").arg(info.programs - 1));
    row(tr("Position range:"), units.arg(info.minPosition).arg(info.maxPosition));
    row(tr("Outputs with dead time:"), QString::number(info.deadTimeOutputs));
    row(tr("Maximum dead time:"),
        tr("%1 ms").arg(QLocale().toString(info.maxDeadTime / 10.0, 'f', 1)));
    if (m_workspace->infoFromDevice()) {
        row(tr("Programmed cams:"), QString::number(info.programmedCams));
        row(tr("Free cam memory:"), tr("%n cam(s)", nullptr, int(info.freeCams)));
        row(tr("CPU clock:"), info.cpuClock == 1 ? tr("25.2 MHz") : tr("16.7 MHz"));
        row(tr("Temperature:"),
            info.temperature == 255 ? tr("no sensor") : tr("%1 °C").arg(info.temperature));
    }
}

}  // namespace cambench
