#pragma once

#include "ui/protocols/protocol_settings_widget.h"

class QComboBox;
class QLineEdit;

namespace cambench {

// The MC-1 protocol's own settings: which controller to expect
// ("Automatic" probes it; a named variant is checked against what answers)
// and its axes (empty: found with RDTABLE; "1,2": those).
class Mc1SettingsWidget : public ProtocolSettingsWidget {
    Q_OBJECT
public:
    explicit Mc1SettingsWidget(QWidget* parent = nullptr);

    void load(const comm::ProtocolSettings& settings) override;
    void store(comm::ProtocolSettings& settings) const override;

    QComboBox* variant() const { return m_variant; }
    QLineEdit* axes() const { return m_axes; }

private:
    QComboBox* m_variant;
    QLineEdit* m_axes;
};

}  // namespace cambench
