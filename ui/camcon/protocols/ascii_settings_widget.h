#pragma once

#include "ui/protocols/protocol_settings_widget.h"

class QSpinBox;

namespace cambench {

// CamCon ASCII: the device number and this PC's number on a Multiuser bus
// (a Standard line has one device and needs neither).
class AsciiSettingsWidget : public ProtocolSettingsWidget {
    Q_OBJECT
public:
    explicit AsciiSettingsWidget(bool multiuser, QWidget* parent = nullptr);

    void load(const comm::ProtocolSettings& settings) override;
    void store(comm::ProtocolSettings& settings) const override;

    QSpinBox* deviceNumber() const { return m_device; }
    QSpinBox* pcNumber() const { return m_pcNumber; }

private:
    QSpinBox* m_device;
    QSpinBox* m_pcNumber;
};

}  // namespace cambench
