#pragma once

#include "ui/camcon/protocols/ascii_settings_widget.h"

namespace cambench {

class CamBusView;

// Cam-BUS: the CamCon to talk to and this PC's own number on the bus
// (default 63; no other user may have it), as for Multiuser, and below them
// the bus as the PC hears it.
class CamBusSettingsWidget : public AsciiSettingsWidget {
    Q_OBJECT
public:
    explicit CamBusSettingsWidget(QWidget* parent = nullptr);

    CamBusView* busView() const { return m_view; }

private:
    CamBusView* m_view;
};

}  // namespace cambench
