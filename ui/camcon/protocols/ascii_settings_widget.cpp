#include "ascii_settings_widget.h"

#include <QFormLayout>
#include <QSpinBox>

namespace cambench {

namespace {
const QString kDevice = QStringLiteral("device");
const QString kPcNumber = QStringLiteral("pcNumber");
}  // namespace

AsciiSettingsWidget::AsciiSettingsWidget(bool multiuser, QWidget* parent)
    : ProtocolSettingsWidget(parent), m_device(new QSpinBox), m_pcNumber(new QSpinBox) {
    m_device->setRange(0, 63);
    m_device->setToolTip(tr("Multiuser: the number of the CamCon to talk to (0–63)."));
    m_pcNumber->setRange(0, 63);
    m_pcNumber->setValue(63);
    m_pcNumber->setToolTip(tr("Multiuser: this PC's own number on the bus (0–63)."));
    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    form->addRow(tr("Device number:"), m_device);
    form->addRow(tr("PC number:"), m_pcNumber);
    // A Standard line is point to point: the numbers mean nothing there.
    m_device->setEnabled(multiuser);
    m_pcNumber->setEnabled(multiuser);
}

void AsciiSettingsWidget::load(const comm::ProtocolSettings& settings) {
    const QVariantMap map = settings.toMap();
    m_device->setValue(map.value(kDevice, m_device->value()).toInt());
    m_pcNumber->setValue(map.value(kPcNumber, m_pcNumber->value()).toInt());
}

void AsciiSettingsWidget::store(comm::ProtocolSettings& settings) const {
    QVariantMap map = settings.toMap();
    map.insert(kDevice, m_device->value());
    map.insert(kPcNumber, m_pcNumber->value());
    settings.fromMap(map);
}

}  // namespace cambench
