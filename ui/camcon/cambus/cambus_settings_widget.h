#pragma once

#include "ui/protocols/protocol_options_form.h"

namespace cambench {

class CamBusView;

// Cam-BUS: the fields of its options (the CamCon to talk to and this PC's
// own number on the bus, default 63, which no other user may have), and
// below them the bus as the PC hears it.
class CamBusSettingsWidget : public ProtocolOptionsForm {
    Q_OBJECT
public:
    explicit CamBusSettingsWidget(QWidget* parent = nullptr);

    CamBusView* busView() const { return m_view; }

private:
    CamBusView* m_view;
};

}  // namespace cambench
