#pragma once

#include "model/camcon/device_info.h"

#include <QDialog>

class QSpinBox;

namespace cambench {

// The capacities of the device a new offline project is made for.
class NewProjectDialog : public QDialog {
    Q_OBJECT
public:
    explicit NewProjectDialog(const DeviceInfo& start, QWidget* parent = nullptr);

    DeviceInfo capacities() const;

private:
    DeviceInfo m_start;
    QSpinBox* m_outputs;
    QSpinBox* m_inputs;
    QSpinBox* m_programs;
    QSpinBox* m_min;
    QSpinBox* m_max;
    QSpinBox* m_deadTimeOutputs;
};

}  // namespace cambench
