#pragma once

#include "ui/protocols/protocol_settings_widget.h"

class QComboBox;

namespace cambench {

// The MC-1 protocol's own setting: which controller to expect. "Automatic"
// probes it; a named variant is checked against what answers.
class Mc1SettingsWidget : public ProtocolSettingsWidget {
    Q_OBJECT
public:
    explicit Mc1SettingsWidget(QWidget* parent = nullptr);

    void load(const comm::ProtocolSettings& settings) override;
    void store(comm::ProtocolSettings& settings) const override;

    QComboBox* variant() const { return m_variant; }

private:
    QComboBox* m_variant;
};

}  // namespace cambench
