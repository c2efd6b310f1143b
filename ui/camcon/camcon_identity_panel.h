#pragma once

#include <QWidget>

class QFormLayout;

namespace cambench {

class DeviceSession;
class Workspace;

// The connection page's "Device" box on a CamCon: firmware, device number,
// outputs, programs, memory and temperature of the connected device. The
// last device's identity, offline or before the one on the line has
// answered, is greyed and says so.
class CamConIdentityPanel : public QWidget {
    Q_OBJECT
public:
    CamConIdentityPanel(DeviceSession* session, Workspace* workspace, QWidget* parent = nullptr);

private:
    void showInfo();

    DeviceSession* m_session;
    Workspace* m_workspace;
    QFormLayout* m_info;
};

}  // namespace cambench
