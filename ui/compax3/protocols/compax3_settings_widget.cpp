#include "compax3_settings_widget.h"

#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>

namespace cambench {

namespace {
const QString kDevice = QStringLiteral("device");
}  // namespace

Compax3SettingsWidget::Compax3SettingsWidget(bool rs485, QWidget* parent)
    : ProtocolSettingsWidget(parent), m_address(new QSpinBox) {
    m_address->setObjectName(QStringLiteral("compax3Address"));
    m_address->setRange(0, 99);
    m_address->setToolTip(
        tr("The drive's RS485 address (C3 ServoManager, \"RS485 settings\"). "
           "Scan bus lists the addresses that answer."));
    auto* note =
        new QLabel(rs485 ? tr("RS485, 115200 8N1 unless set otherwise in the drive.")
                         : tr("RS232, 115200 8N1 with RTS/CTS unless set otherwise in the drive; a "
                              "null-modem cable with RTS/CTS."));
    note->setWordWrap(true);
    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    if (rs485)
        form->addRow(tr("Drive address:"), m_address);
    else
        m_address->hide();
    form->addRow(note);
}

void Compax3SettingsWidget::load(const comm::ProtocolSettings& settings) {
    m_address->setValue(settings.toMap().value(kDevice, m_address->value()).toInt());
}

void Compax3SettingsWidget::store(comm::ProtocolSettings& settings) const {
    QVariantMap map = settings.toMap();
    map.insert(kDevice, m_address->value());
    settings.fromMap(map);
}

}  // namespace cambench
