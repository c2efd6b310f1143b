#include "connection_page.h"

#include <QCoreApplication>

#include "device_session.h"
#include "family_gui.h"
#include "sentence.h"

#include "ui/protocols/protocol_options_form.h"
#include "ui/protocols/protocol_settings_widget.h"

#include "comm/device/family_registry.h"
#include "comm/device/protocol_registry.h"
#include "comm/ports/serial_port_list.h"
#include "comm/usecases/detect_device.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QToolButton>

namespace cambench {

namespace {
const QString kSimPort = QStringLiteral("sim");

bool isSimulated(const QString& port) {
    return port == kSimPort || port.startsWith(kSimPort + QLatin1Char(':'));
}
}  // namespace

ConnectionPage::ConnectionPage(DeviceSession* session, QWidget* parent)
    : SectionPage(parent), m_session(session) {
    auto* line = new QGroupBox(tr("Line"));
    auto* form = new QFormLayout(line);
    m_simNote = new QLabel(
        tr("You are working on the simulated demo device: no machine is attached, and nothing "
           "you write here reaches a real device. To work on a machine, choose its port below "
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
    m_detect = new QPushButton(tr("Detect"));
    m_detect->setObjectName(QStringLiteral("detectButton"));
    m_detect->setToolTip(
        tr("Find out what is on this port: each device family's protocols are tried at their "
           "usual line settings, with identification queries only."));
    auto* portRow = new QHBoxLayout;
    portRow->addWidget(m_port, 1);
    portRow->addWidget(refresh);
    portRow->addWidget(m_detect);
    form->addRow(tr("Port:"), portRow);

    m_family = new QComboBox;
    m_family->setObjectName(QStringLiteral("familyBox"));
    form->addRow(tr("Device family:"), m_family);
    m_protocol = new QComboBox;
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
    m_detectResult = new QLabel;
    m_detectResult->setObjectName(QStringLiteral("detectResult"));
    m_detectResult->setWordWrap(true);
    m_detectResult->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_detectResult->hide();
    form->addRow(m_detectResult);

    m_deviceHint = new QLabel;
    m_deviceHint->setObjectName(QStringLiteral("deviceNumberHint"));
    m_deviceHint->setWordWrap(true);
    m_deviceHint->hide();
    form->addRow(m_deviceHint);

    auto* bus = new QGroupBox(tr("Devices on the line"));
    m_bus = bus;
    auto* busLayout = new QVBoxLayout(bus);
    m_scan = new QPushButton(tr("Scan bus"));
    m_scan->setToolTip(
        tr("Ask every device number of a bus for an answer, or identify the one device of a "
           "point-to-point line."));
    m_devices = new QListWidget;
    m_devices->setObjectName(QStringLiteral("busDevices"));
    m_devices->setToolTip(tr("Double-click a device to work with it."));
    busLayout->addWidget(m_scan, 0, Qt::AlignLeft);
    busLayout->addWidget(m_devices);

    auto* identity = new QGroupBox(tr("Device"));
    m_identity = identity;
    m_identityPanels = new QVBoxLayout(identity);

    auto* left = new QVBoxLayout;
    left->addWidget(line);
    left->addWidget(bus, 1);
    auto* layout = new QHBoxLayout(this);
    layout->addLayout(left, 3);
    layout->addWidget(identity, 2);

    fillPorts();
    fillFamilies();
    fillProtocols();
    showProtocolWidget();
    // A rebuilt window (language switch) shows the line in use.
    if (m_session->state() != comm::ConnectionState::Disconnected || m_session->isRetrying())
        showConnection(m_session->connection(), m_session->protocol());
    connect(refresh, &QToolButton::clicked, this, &ConnectionPage::fillPorts);
    connect(m_detect, &QPushButton::clicked, this, &ConnectionPage::detect);
    connect(m_family, &QComboBox::currentIndexChanged, this, &ConnectionPage::fillProtocols);
    connect(m_protocol, &QComboBox::currentIndexChanged, this, &ConnectionPage::protocolChanged);
    connect(m_connect, &QPushButton::clicked, this,
            [this] { m_session->connectTo(connectionSettings(), protocolSettings()); });
    connect(m_disconnect, &QPushButton::clicked, m_session, &DeviceSession::disconnectFromDevice);
    // Enter in the port field connects, as the button does.
    connect(m_port->lineEdit(), &QLineEdit::returnPressed, m_connect, &QPushButton::click);
    connect(m_port, &QComboBox::currentTextChanged, this, &ConnectionPage::updateButtons);
    connect(m_scan, &QPushButton::clicked, this, &ConnectionPage::scanBus);
    connect(m_devices, &QListWidget::itemActivated, this, [this](QListWidgetItem* item) {
        const int device = item->data(Qt::UserRole).toInt();
        // From now on the STOP would reach the other drive: while this one
        // may move, asked first (STOP offered), as Disconnect does.
        if (device != m_session->protocol().device() &&
            !m_session->mayLeaveDevice(tr("Switch to device %1").arg(device)))
            return;
        chooseDevice(device);
    });
    connect(m_session, &DeviceSession::stateChanged, this, [this](comm::ConnectionState state) {
        if (state == comm::ConnectionState::Connecting) m_busSearched = false;
    });
    connect(m_session, &DeviceSession::identifyProblemChanged, this,
            &ConnectionPage::findBusDevice);
    connect(m_session, &DeviceSession::stateChanged, this, &ConnectionPage::updateButtons);
    connect(m_session, &DeviceSession::stateChanged, this, &ConnectionPage::showIdentityPanel);
    connect(m_session, &DeviceSession::stateChanged, this, &ConnectionPage::showConnectFailure);
    connect(m_session, &DeviceSession::stateChanged, this, &ConnectionPage::showSimulatedNote);
    updateButtons();
    showIdentityPanel();
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
    if (const comm::ProtocolInfo* info = comm::ProtocolRegistry::instance().find(id))
        setFamily(info->familyId);
    const int index = m_protocol->findData(id);
    if (index >= 0) m_protocol->setCurrentIndex(index);
}

void ConnectionPage::setFamily(const QString& id) {
    const int index = m_family->findData(id);
    if (index >= 0) m_family->setCurrentIndex(index);
}

QString ConnectionPage::family() const {
    return m_family->currentData().toString();
}

void ConnectionPage::fillFamilies() {
    auto* model = new QStandardItemModel(m_family);
    for (const comm::FamilyInfo* info : comm::FamilyRegistry::instance().all()) {
        // A family not built yet is shown, greyed, with the reason: a
        // technician looking for it learns that it is coming, not that it
        // does not exist.
        auto* item = new QStandardItem(
            info->built ? info->title
                        : tr("%1 (not built into this CamBench yet)").arg(info->title));
        item->setData(info->id, Qt::UserRole);
        if (!info->built) {
            item->setFlags(item->flags() & ~Qt::ItemIsEnabled);
            item->setToolTip(tr("Its protocol, simulator and pages are not built yet."));
        }
        model->appendRow(item);
    }
    m_family->setModel(model);
}

void ConnectionPage::fillProtocols() {
    const QString chosen = m_protocol->currentData().toString();
    const QSignalBlocker quiet(m_protocol);
    m_protocol->clear();
    for (const comm::ProtocolInfo* info : comm::ProtocolRegistry::instance().all()) {
        if (info->familyId == family()) m_protocol->addItem(protocolTitle(*info), info->id);
    }
    const int index = m_protocol->findData(chosen);
    m_protocol->setCurrentIndex(index >= 0 ? index : 0);
    if (index < 0) protocolChanged();  // another family: its first protocol
}

void ConnectionPage::protocolChanged() {
    if (const comm::ProtocolInfo* info = currentProtocol())
        m_baud->setCurrentText(QString::number(info->defaultSerial.baud));
    showProtocolWidget();
    updateButtons();
}

void ConnectionPage::detect() {
    const comm::ConnectionSettings where = connectionSettings();
    if (where.port.isEmpty()) {
        showDetectResult(Error::usage(tr("Choose or type a port first.")));
        return;
    }
    if (m_session->state() != comm::ConnectionState::Disconnected || m_session->wantsConnection()) {
        // Detect needs the port to itself.
        const auto answer = QMessageBox::question(
            this, tr("Detect"),
            tr("Detect closes the connection to %1 and then tries each device family on %2. "
               "Nothing is written to a device; your edits stay. Go on?")
                .arg(isSimulated(m_session->connection().port) ? tr("the simulated device")
                                                               : m_session->connection().port,
                     where.port),
            QMessageBox::Yes | QMessageBox::No, QMessageBox::No);
        if (answer != QMessageBox::Yes) return;
    }
    // Also a connect on its way to the worker lets go of the port first;
    // cancelled at the question before leaving a moving device: nothing more.
    if (!m_session->disconnectFromDevice()) return;
    m_detect->setEnabled(false);
    m_detectResult->setText(tr("Detecting on %1…").arg(where.port));
    m_detectResult->setPalette(QPalette());
    m_detectResult->show();
    // The device and PC numbers in the form are tried for the protocol
    // shown; the others are tried with their defaults.
    const comm::ProtocolSettingsPtr shown = protocolSettings();
    const usecases::DetectSettings settings = [shown](const comm::ProtocolInfo& protocol) {
        return protocol.id == shown->protocolId()
                   ? shown
                   : comm::ProtocolSettingsPtr(protocol.makeSettings());
    };
    const QString port = where.port;
    m_session->worker().run<Result<usecases::DetectResult>>(
        this, comm::JobPriority::User, tr("Detect device on %1").arg(port),
        [port, settings](comm::JobContext& job) {
            return usecases::detectDevice(port, job, settings);
        },
        [this](Result<usecases::DetectResult> result) { showDetectResult(result); });
}

void ConnectionPage::showDetectResult(const Result<usecases::DetectResult>& result) {
    m_detect->setEnabled(true);
    QPalette alarm = m_detectResult->palette();
    alarm.setColor(QPalette::WindowText, QColor(0xd0, 0x30, 0x20));
    if (!result) {
        m_detectResult->setText(
            tr("Detect could not use the port: %1").arg(asSentence(result.error().message)));
        m_detectResult->setPalette(alarm);
        Q_EMIT statusMessage(m_detectResult->text());
        return;
    }
    m_detectResult->setToolTip({});
    if (const usecases::DetectAttempt* found = result->found()) {
        m_failure->hide();  // an earlier connect's failure is not this port's state
        setProtocol(found->protocolId);
        m_baud->setCurrentText(QString::number(found->serial.baud));
        m_detectResult->setPalette(QPalette());
        m_detectResult->setText(tr("Found on %1: %2. The protocol and baud rate are filled in; "
                                   "press Connect to work with it.")
                                    .arg(result->port, usecases::attemptLine(*found)));
        Q_EMIT statusMessage(tr("Detect: %1").arg(usecases::attemptLine(*found)));
        return;
    }
    // One short line per try; what each failure said in full in the tooltip.
    QStringList tried;
    QStringList details;
    for (const usecases::DetectAttempt& attempt : result->attempts) {
        const comm::ProtocolInfo* protocol =
            comm::ProtocolRegistry::instance().find(attempt.protocolId);
        tried << tr("• %1, %2: no answer")
                     .arg(protocol ? protocolTitle(*protocol) : attempt.protocolId,
                          usecases::lineText(attempt.serial));
        details << usecases::attemptLine(attempt);
    }
    m_detectResult->setToolTip(details.join(QLatin1Char('\n')));
    m_detectResult->setText(
        (result->cancelled ? tr("Detect was cancelled; nothing answered on %1 so far. Tried:")
                           : tr("Nothing answered on %1. Tried:"))
            .arg(result->port) +
        QLatin1Char('\n') + tried.join(QLatin1Char('\n')) + QLatin1Char('\n') +
        tr("Check the cable, the device's power and its interface settings (for an RS485 bus "
           "also the device number), then Detect again."));
    m_detectResult->setPalette(alarm);
    Q_EMIT statusMessage(tr("Detect: nothing answered on %1").arg(result->port));
}

const comm::ProtocolInfo* ConnectionPage::currentProtocol() const {
    return comm::ProtocolRegistry::instance().find(m_protocol->currentData().toString());
}

QString ConnectionPage::protocolTitle(const comm::ProtocolInfo& info) {
    // Registered before any translator was installed: translated here.
    const QString title = info.choiceTitle.isEmpty() ? info.title : info.choiceTitle;
    return QCoreApplication::translate("cambench::comm", title.toUtf8().constData());
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
    if (!info) return;
    // A protocol shows a widget of its own where it has one, else the
    // fields of the options it declares.
    m_protocolWidget = ProtocolWidgetRegistry::instance().create(info->id);
    if (!m_protocolWidget && (!info->options.isEmpty() || !info->note.isEmpty()))
        m_protocolWidget = new ProtocolOptionsForm(*info);
    if (!m_protocolWidget) return;
    m_protocolBox->addWidget(m_protocolWidget);
    connect(m_protocolWidget, &ProtocolSettingsWidget::protocolRequested, this,
            &ConnectionPage::setProtocol, Qt::QueuedConnection);
    // A number typed in (the device number) says what it takes to reach it.
    for (QSpinBox* number : m_protocolWidget->findChildren<QSpinBox*>())
        connect(number, &QSpinBox::valueChanged, this, &ConnectionPage::updateButtons);
}

void ConnectionPage::updateButtons() {
    const auto state = m_session->state();
    // Retrying a lost line is not idle: Disconnect stops the retries.
    const bool idle = state == comm::ConnectionState::Disconnected && !m_session->isRetrying();
    // "Reconnect" only for the line in use; another port or protocol is a Connect.
    const comm::ConnectionSettings shown = connectionSettings();
    const bool sameLine = !idle && shown.port == m_session->connection().port &&
                          shown.protocol == m_session->protocol().protocolId();
    m_connect->setEnabled(state != comm::ConnectionState::Connecting);
    m_connect->setText(sameLine ? tr("Reconnect") : tr("Connect"));
    m_disconnect->setEnabled(!idle || m_session->wantsConnection());
    // A scan only where the protocol has a bus.
    const comm::ProtocolInfo* info = currentProtocol();
    m_bus->setVisible(info && info->isBus);
    m_scan->setEnabled(m_session->isOnline() && sameLine);
    // A device number typed in is reached by a reconnect: said so.
    const int wanted = protocolSettings()->device();
    m_deviceHint->setVisible(sameLine && wanted != m_session->protocol().device());
    m_deviceHint->setText(tr("Reconnect to reach device %1.").arg(wanted));
}

void ConnectionPage::scanBus() {
    m_devices->clear();
    m_scan->setEnabled(false);
    Q_EMIT statusMessage(tr("Scanning the bus…"));
    const comm::ProtocolInfo* info =
        comm::ProtocolRegistry::instance().find(m_session->protocol().protocolId());
    if (!info || !info->isBus) {
        // A point-to-point line has exactly one device: identify it.
        m_session->worker().run<Result<QString>>(
            this, comm::JobPriority::User, tr("Identify device"),
            [](comm::JobContext& job) -> Result<QString> {
                if (!job.device()) return Error::communication(tr("not connected"));
                return job.device()->identify();
            },
            [this](Result<QString> identity) {
                updateButtons();
                if (!identity) {
                    Q_EMIT statusMessage(
                        tr("Identifying the device failed: %1").arg(identity.error().message));
                    return;
                }
                auto* item = new QListWidgetItem(*identity);
                item->setData(Qt::UserRole, m_session->protocol().device());
                m_devices->addItem(item);
                Q_EMIT statusMessage(tr("%n device(s) found", nullptr, 1));
            });
        return;
    }
    runBusScan([this](const Result<QList<int>>& devices) { showScanResult(devices); });
}

void ConnectionPage::runBusScan(std::function<void(const Result<QList<int>>&)> done) {
    const comm::ProtocolInfo* info =
        comm::ProtocolRegistry::instance().find(m_session->protocol().protocolId());
    const int last = info ? info->lastDevice : 0;
    m_session->worker().run<Result<QList<int>>>(
        this, comm::JobPriority::User, tr("Scan bus"),
        [last](comm::JobContext& job) -> Result<QList<int>> {
            if (!job.device()) return Error::communication(tr("not connected"));
            return job.device()->scanBus(
                0, last, [&job](qint64 done, qint64 total) { job.progress(done, total); });
        },
        [done = std::move(done)](Result<QList<int>> devices) { done(devices); });
}

void ConnectionPage::chooseDevice(int device) {
    if (const comm::ProtocolInfo* info = currentProtocol(); info && m_protocolWidget) {
        std::unique_ptr<comm::ProtocolSettings> settings = info->makeSettings();
        m_protocolWidget->store(*settings);
        settings->setDevice(device);
        m_protocolWidget->load(*settings);
    }
    m_session->setDevice(device);
    // The field's change above asked before the session had the device:
    // its "Reconnect to reach device N" would say a reconnect is needed
    // for the device CamBench already talks to.
    updateButtons();
    Q_EMIT deviceSelected(device);
}

void ConnectionPage::findBusDevice() {
    if (!m_findsBusDevice || m_busSearched || m_session->identifyProblem().isEmpty()) return;
    const comm::ProtocolInfo* info =
        comm::ProtocolRegistry::instance().find(m_session->protocol().protocolId());
    if (!info || !info->isBus) return;
    m_busSearched = true;  // once a connect: a device that stops answering stays said
    const int asked = m_session->protocol().device();
    runBusScan([this, asked](const Result<QList<int>>& devices) {
        showScanResult(devices);
        if (!devices || devices->isEmpty() || devices->contains(asked) ||
            m_session->protocol().device() != asked || !m_session->isOnline())
            return;
        const int found = devices->first();
        QStringList numbers;
        for (int device : *devices) numbers << QString::number(device);
        Q_EMIT statusMessage(tr("Device %1 does not answer on the bus; device %2 does (the bus "
                                "has %3): CamBench talks to device %2 now.")
                                 .arg(asked)
                                 .arg(found)
                                 .arg(numbers.join(QStringLiteral(", "))));
        chooseDevice(found);
    });
}

void ConnectionPage::showScanResult(const Result<QList<int>>& devices) {
    updateButtons();
    if (!devices) {
        Q_EMIT statusMessage(tr("Bus scan failed: %1").arg(devices.error().message));
        return;
    }
    const comm::FamilyInfo* family =
        comm::FamilyRegistry::instance().find(sessionFamily(*m_session));
    const QString title = family ? family->title : QString();
    const comm::ProtocolInfo* protocol =
        comm::ProtocolRegistry::instance().find(m_session->protocol().protocolId());
    const bool addresses = protocol && protocol->numbersAreAddresses;
    for (int device : devices.value()) {
        auto* item =
            new QListWidgetItem(addresses ? tr("%1, address %2").arg(title).arg(device)
                                          : tr("%1, device number %2").arg(title).arg(device));
        item->setData(Qt::UserRole, device);
        m_devices->addItem(item);
    }
    Q_EMIT statusMessage(tr("%n device(s) found", nullptr, int(devices->size())));
}

void ConnectionPage::showSimulatedNote() {
    const bool simulated = isSimulated(m_session->connection().port);
    m_simNote->setVisible(simulated && m_session->state() != comm::ConnectionState::Disconnected);
}

void ConnectionPage::showConnectFailure() {
    const comm::ConnectionState state = m_session->state();
    // What a scan found was on the line then; off it, the list would claim
    // devices nobody can see now.
    if (state != comm::ConnectionState::Connected) m_devices->clear();
    // What Detect found has been acted on (or another line chosen).
    if (state == comm::ConnectionState::Connected) m_detectResult->hide();
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

void ConnectionPage::addIdentityPanel(const QString& familyId, QWidget* panel) {
    if (!panel) return;
    m_identityPanels->addWidget(panel);
    m_panels.insert(familyId, panel);
    showIdentityPanel();
}

void ConnectionPage::showIdentityPanel() {
    // The family of the chosen protocol tells what it knows of its device.
    const QString family = sessionFamily(*m_session);
    for (auto it = m_panels.cbegin(); it != m_panels.cend(); ++it)
        it.value()->setVisible(it.key() == family);
    m_identity->setVisible(m_panels.contains(family));
}

}  // namespace cambench
