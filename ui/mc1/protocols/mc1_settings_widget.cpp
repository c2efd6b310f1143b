#include "mc1_settings_widget.h"

#include "comm/mc1/mc1_protocol.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>

namespace cambench {

Mc1SettingsWidget::Mc1SettingsWidget(QWidget* parent)
    : ProtocolSettingsWidget(parent), m_variant(new QComboBox) {
    m_variant->setObjectName(QStringLiteral("mc1Variant"));
    m_variant->addItem(tr("Automatic (probe the controller)"), QStringLiteral("auto"));
    for (comm::Mc1Variant variant : comm::allMc1Variants())
        m_variant->addItem(comm::mc1VariantName(variant), comm::mc1VariantKey(variant));
    m_variant->setToolTip(
        tr("Automatic asks the controller and names what it found. A variant "
           "chosen here is checked against what answers."));
    auto* note =
        new QLabel(tr("RS232, 8N1. MC100: 9600 baud, RxD/TxD crossed. MC200: the baud "
                      "rate set in the controller, a 1:1 cable; CamBench holds DTR high "
                      "and RTS low, which power its interface."));
    note->setWordWrap(true);
    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    form->addRow(tr("Controller:"), m_variant);
    form->addRow(note);
}

void Mc1SettingsWidget::load(const comm::ProtocolSettings& settings) {
    const QString key = settings.toMap().value(QStringLiteral("variant")).toString();
    m_variant->setCurrentIndex(qMax(0, m_variant->findData(key)));
}

void Mc1SettingsWidget::store(comm::ProtocolSettings& settings) const {
    QVariantMap map = settings.toMap();
    map.insert(QStringLiteral("variant"), m_variant->currentData().toString());
    settings.fromMap(map);
}

}  // namespace cambench
