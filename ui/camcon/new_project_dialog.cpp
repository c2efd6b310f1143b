#include "new_project_dialog.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QSpinBox>

namespace cambench {

namespace {
QSpinBox* spin(int min, int max, int value, int step = 1) {
    auto* box = new QSpinBox;
    box->setRange(min, max);
    box->setSingleStep(step);
    box->setValue(value);
    return box;
}
}  // namespace

NewProjectDialog::NewProjectDialog(const DeviceInfo& start, QWidget* parent)
    : QDialog(parent),
      m_start(start),
      m_outputs(spin(8, 200, start.outputs, 8)),
      m_inputs(spin(0, 200, start.inputs, 8)),
      m_programs(spin(1, 32767, start.programs)),
      m_min(spin(-2147483647, 2147483647, start.minPosition)),
      m_max(spin(-2147483647, 2147483647, start.maxPosition)),
      m_deadTimeOutputs(spin(0, 200, start.deadTimeOutputs)) {
    setWindowTitle(tr("New project"));
    auto* form = new QFormLayout(this);
    form->addRow(tr("Outputs (multiple of 8):"), m_outputs);
    form->addRow(tr("Inputs (multiple of 8):"), m_inputs);
    form->addRow(tr("Programs:"), m_programs);
    form->addRow(tr("Smallest position (IMIN):"), m_min);
    form->addRow(tr("Largest position (IMAX):"), m_max);
    form->addRow(tr("Outputs with dead time:"), m_deadTimeOutputs);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    form->addRow(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
}

DeviceInfo NewProjectDialog::capacities() const {
    DeviceInfo info;
    info.maxDeadTime = m_start.maxDeadTime;
    // The device counts outputs and inputs in groups of 8.
    info.outputs = m_outputs->value() / 8 * 8;
    info.inputs = m_inputs->value() / 8 * 8;
    info.programs = m_programs->value();
    info.minPosition = std::min(m_min->value(), m_max->value());
    info.maxPosition = std::max(m_min->value(), m_max->value());
    info.deadTimeOutputs = std::min(m_deadTimeOutputs->value(), info.outputs);
    return info;
}

}  // namespace cambench
