#pragma once

#include "section_page.h"

#include "comm/device/connection_settings.h"
#include "comm/device/protocol_settings.h"
#include "model/result.h"

#include <QMap>

#include <functional>

class QComboBox;
class QFormLayout;
class QGroupBox;
class QLabel;
class QListWidget;
class QPushButton;
class QVBoxLayout;

namespace cambench {
namespace comm {
struct ProtocolInfo;
}
namespace usecases {
struct DetectResult;
}

class DeviceSession;
class ProtocolSettingsWidget;

// Where the device is (serial port, tcp://, simulated), the protocol and
// its numbers; a bus scan that lists the devices on an RS485 line; and the
// identity of the connected device.
class ConnectionPage : public SectionPage {
    Q_OBJECT
public:
    explicit ConnectionPage(DeviceSession* session, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Connection"); }

    comm::ConnectionSettings connectionSettings() const;
    comm::ProtocolSettingsPtr protocolSettings() const;
    void setPort(const QString& port);
    // Shows a connection's line and protocol settings in the form.
    void showConnection(const comm::ConnectionSettings& connection,
                        const comm::ProtocolSettings& protocol);
    // A ProtocolRegistry id: "standard", "multiuser", ...
    void setProtocol(const QString& id);
    // A FamilyRegistry id: the protocol list shows that family's protocols.
    void setFamily(const QString& id);
    QString family() const;

    // What a family shows of the connected (or last) device, in the
    // "Device" box while its protocol is chosen.
    void addIdentityPanel(const QString& familyId, QWidget* panel);

    void scanBus();
    // On a bus, when the device number asked for does not identify itself
    // after a connect, the bus is scanned and the first device that answers
    // is chosen (said in the status bar): a connection starts on a device
    // that answers. Off in a machine, whose file names each device's
    // number: there another number is never chosen for it.
    void setFindsBusDevice(bool finds) { m_findsBusDevice = finds; }
    // Tries each family's protocols on the chosen port (closing the
    // connection first) and fills in what answered.
    void detect();

Q_SIGNALS:
    // The user picked another device of the bus: read its identity.
    void deviceSelected(int device);

private:
    void fillPorts();
    const comm::ProtocolInfo* currentProtocol() const;
    static QString protocolTitle(const comm::ProtocolInfo& info);
    void updateButtons();
    void showIdentityPanel();
    void showConnectFailure();
    void showSimulatedNote();
    void showScanResult(const Result<QList<int>>& devices);
    // Asks the bus which devices answer (scanBus's job).
    void runBusScan(std::function<void(const Result<QList<int>>&)> done);
    // `device` of the bus from now on: the form, the session, its identity read.
    void chooseDevice(int device);
    // The device asked for did not identify itself: one that answers.
    void findBusDevice();
    // Puts the settings widget of the protocol chosen in place.
    void showProtocolWidget();
    void fillFamilies();
    // The chosen family's protocols, keeping the chosen one when it is one.
    void fillProtocols();
    // Another protocol chosen: its baud rate and its settings widget.
    void protocolChanged();
    void showDetectResult(const Result<usecases::DetectResult>& result);

    DeviceSession* m_session;
    QComboBox* m_port;
    QComboBox* m_family;
    QComboBox* m_protocol;
    QComboBox* m_baud;
    QVBoxLayout* m_protocolBox;  // holds the chosen protocol's settings widget
    ProtocolSettingsWidget* m_protocolWidget = nullptr;
    QPushButton* m_connect;
    QPushButton* m_disconnect;
    QPushButton* m_scan;
    QPushButton* m_detect;
    QLabel* m_detectResult;  // what Detect found, or everything it tried
    QListWidget* m_devices;
    QVBoxLayout* m_identityPanels;
    QMap<QString, QWidget*> m_panels;  // per family
    QGroupBox* m_identity;
    QLabel* m_failure;  // the last connect that failed: where, what, what to do
    QLabel* m_simNote;  // on the simulated device: says so, and the way to a real one
    bool m_findsBusDevice = true;
    bool m_busSearched = false;      // since the last connect
    QLabel* m_deviceHint = nullptr;  // "Reconnect to reach device 5"
    QGroupBox* m_bus = nullptr;      // the bus scan, only for a protocol with a bus
};

}  // namespace cambench
