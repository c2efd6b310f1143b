#pragma once

#include "ui/protocols/protocol_settings_widget.h"

class QSpinBox;

namespace cambench {

// A Compax3 connection's own settings: the drive's address on RS485
// (0..99; RS232 has none) and what the cable needs.
class Compax3SettingsWidget : public ProtocolSettingsWidget {
    Q_OBJECT
public:
    explicit Compax3SettingsWidget(bool rs485, QWidget* parent = nullptr);

    void load(const comm::ProtocolSettings& settings) override;
    void store(comm::ProtocolSettings& settings) const override;

    QSpinBox* address() const { return m_address; }

private:
    QSpinBox* m_address;
};

}  // namespace cambench
