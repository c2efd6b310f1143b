#pragma once

#include "protocol_settings_widget.h"

#include <QHash>

class QComboBox;
class QFormLayout;
class QSpinBox;

namespace cambench {

namespace comm {
struct ProtocolInfo;
}

// The fields of a protocol's options on the connection page, built from
// what the protocol declares (ProtocolInfo::options): a number field for a
// number in its range, a list for a choice; with the protocol's note below
// them. A protocol needs no widget of its own for its options; one that
// shows more (Cam-BUS: the bus as the PC hears it) builds on this form.
class ProtocolOptionsForm : public ProtocolSettingsWidget {
    Q_OBJECT
public:
    explicit ProtocolOptionsForm(const comm::ProtocolInfo& protocol, QWidget* parent = nullptr);

    void load(const comm::ProtocolSettings& settings) override;
    void store(comm::ProtocolSettings& settings) const override;

    // The field of number option `name` ("pc-number"), or null.
    QSpinBox* numberField(const QString& name) const;

protected:
    QFormLayout* form() const { return m_form; }

private:
    QFormLayout* m_form;
    QHash<QString, QSpinBox*> m_numbers;  // by settings key
    QHash<QString, QComboBox*> m_choices;
    QHash<QString, QString> m_keyOfName;  // option name -> settings key
};

}  // namespace cambench
