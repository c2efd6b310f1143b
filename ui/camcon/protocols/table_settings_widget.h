#pragma once

#include "ui/protocols/protocol_settings_widget.h"

class QComboBox;
class QLabel;

namespace cambench {

// The CamCon table interface (3964R/RK512): which variant the device's
// serial mode ("Ser:") is set to. The variants are two protocols of the
// registry; choosing the other one here switches the page to it.
class TableSettingsWidget : public ProtocolSettingsWidget {
    Q_OBJECT
public:
    explicit TableSettingsWidget(const QString& protocolId, QWidget* parent = nullptr);

    void load(const comm::ProtocolSettings& settings) override;
    void store(comm::ProtocolSettings& settings) const override;

    QComboBox* variant() const { return m_variant; }

private:
    QComboBox* m_variant;
    QLabel* m_explanation;
};

}  // namespace cambench
