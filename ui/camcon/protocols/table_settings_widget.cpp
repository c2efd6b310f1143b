#include "table_settings_widget.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>

namespace cambench {

TableSettingsWidget::TableSettingsWidget(const QString& protocolId, QWidget* parent)
    : ProtocolSettingsWidget(parent), m_variant(new QComboBox), m_explanation(new QLabel) {
    m_variant->addItem(tr("3964R n96 (9600 baud, 8N1)"), QStringLiteral("3964r-n96"));
    m_variant->addItem(tr("3964R e38 (38400 baud, 8E1)"), QStringLiteral("3964r-e38"));
    m_variant->setCurrentIndex(qMax(0, m_variant->findData(protocolId)));
    m_variant->setToolTip(tr("The serial mode the device's menu \"Ser:\" shows."));
    m_explanation->setWordWrap(true);
    m_explanation->setText(
        tr("Point to point: no device number. 3964R e38 reaches only the data words 0–127 of "
           "each area: 62 cams per track and no dead-time modes; n96 reaches all."));
    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    form->addRow(tr("Variant:"), m_variant);
    form->addRow(m_explanation);
    connect(m_variant, &QComboBox::currentIndexChanged, this,
            [this] { Q_EMIT protocolRequested(m_variant->currentData().toString()); });
}

void TableSettingsWidget::load(const comm::ProtocolSettings& settings) {
    const QSignalBlocker quiet(m_variant);
    m_variant->setCurrentIndex(qMax(0, m_variant->findData(settings.protocolId())));
}

void TableSettingsWidget::store(comm::ProtocolSettings&) const {
    // The variant is the protocol itself; nothing else to keep.
}

}  // namespace cambench
