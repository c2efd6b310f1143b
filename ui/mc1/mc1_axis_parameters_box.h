#pragma once

#include "comm/mc1/mc1_device.h"

#include <QWidget>

class QLabel;
class QPushButton;

namespace cambench {

class DeviceSession;

// The Axes page's line about the axis parameter numbers (RDSTAT): which
// table is in use - CamBench's provisional guess, said as such, or the
// controller's own loaded from a CSV file (name,axis,parameter) - and
// "Load parameter table…". The file loaded last is remembered and handed
// to the controller again on the next connection; a malformed file is
// refused naming its line, and the table in use stays.
class Mc1AxisParametersBox : public QWidget {
    Q_OBJECT
public:
    explicit Mc1AxisParametersBox(DeviceSession* session, QWidget* parent = nullptr);

    QLabel* sourceLabel() const { return m_source; }
    // Loads `path` (the button's file dialog calls it), hands the table to
    // the controller and remembers the path; false with the reason shown
    // when the file is refused.
    bool load(const QString& path);
    // A controller came on the line: hands it the remembered table.
    void controllerOnLine();
    // The table in use, as the controller connection holds it.
    const comm::Mc1AxisParameterTable& table() const { return m_table; }

Q_SIGNALS:
    // Another table is in use: values read before are not to be trusted.
    void tableChanged();

private:
    // Hands `table` to the controller and shows it.
    void use(const comm::Mc1AxisParameterTable& table);
    void showTable();

    DeviceSession* m_session;
    comm::Mc1AxisParameterTable m_table = comm::mc1ProvisionalAxisParameters();
    QLabel* m_source;
    QPushButton* m_load;
};

}  // namespace cambench
