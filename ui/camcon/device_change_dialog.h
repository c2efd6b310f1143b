#pragma once

#include "model/camcon/carry_over.h"

#include <QDialog>
#include <QMap>

class QRadioButton;

namespace cambench {

class Workspace;
struct DeviceInfo;

// "CamCon 11.10.1994, device 0": a device as the person tells it apart.
QString deviceName(const DeviceInfo& info);

// What the person changed of the values shown, one line per item, each
// with the value the old device held ("Program 0, output 1: 25–60 (read
// from CamCon 11.10.1994, device 0: 20–60)"); values only read are not in it.
QStringList personsChanges(const Workspace& workspace);

// Asked when another device answers than the one the values shown were read
// from, and the person had changed some of them: take the new device's
// values (the default), keep only the changes (each listed) over the new
// device's values, or copy the old device's programs and sections to the
// new one. Closing it keeps the changes: nothing is lost, and nothing of
// the old device is taken as the person's.
class DeviceChangeDialog : public QDialog {
    Q_OBJECT
public:
    DeviceChangeDialog(const QString& oldDevice, const QString& newDevice,
                       const QStringList& changes, QWidget* parent = nullptr);

    CarryOver choice() const;
    void choose(CarryOver carry);
    QString changesText() const { return m_changesText; }

    void reject() override;

private:
    QMap<CarryOver, QRadioButton*> m_options;
    QString m_changesText;
};

}  // namespace cambench
