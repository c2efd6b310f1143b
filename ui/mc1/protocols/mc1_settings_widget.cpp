#include "mc1_settings_widget.h"

#include "comm/mc1/mc1_protocol.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QRegularExpressionValidator>

namespace cambench {

Mc1SettingsWidget::Mc1SettingsWidget(QWidget* parent)
    : ProtocolSettingsWidget(parent), m_variant(new QComboBox), m_axes(new QLineEdit) {
    m_variant->setObjectName(QStringLiteral("mc1Variant"));
    m_variant->addItem(tr("Automatic (probe the controller)"), QStringLiteral("auto"));
    for (comm::Mc1Variant variant : comm::allMc1Variants())
        m_variant->addItem(comm::mc1VariantName(variant), comm::mc1VariantKey(variant));
    m_variant->setToolTip(
        tr("Automatic asks the controller and names what it found. A variant "
           "chosen here is checked against what answers."));
    m_axes->setObjectName(QStringLiteral("mc1Axes"));
    m_axes->setPlaceholderText(tr("found by asking the controller"));
    // Logical axes 1..8 and commas only: a list that could not be read
    // would silently fall back to asking the controller.
    m_axes->setValidator(
        new QRegularExpressionValidator(QRegularExpression(QStringLiteral("[1-8,]*")), m_axes));
    m_axes->setToolTip(
        tr("Empty: an MC200 is asked which axes it has (RDTABLE), and STOP goes to each of "
           "them. Axis numbers such as 1,2 name them instead."));
    auto* note =
        new QLabel(tr("RS232, 8N1. MC100: 9600 baud, RxD/TxD crossed. MC200: the baud "
                      "rate set in the controller, a 1:1 cable; CamBench holds DTR high "
                      "and RTS low, which power its interface."));
    note->setWordWrap(true);
    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    form->addRow(tr("Controller:"), m_variant);
    form->addRow(tr("Axes:"), m_axes);
    form->addRow(note);
}

void Mc1SettingsWidget::load(const comm::ProtocolSettings& settings) {
    const QString key = settings.toMap().value(QStringLiteral("variant")).toString();
    m_variant->setCurrentIndex(qMax(0, m_variant->findData(key)));
    m_axes->setText(settings.toMap().value(QStringLiteral("axes")).toString());
}

void Mc1SettingsWidget::store(comm::ProtocolSettings& settings) const {
    QVariantMap map = settings.toMap();
    map.insert(QStringLiteral("variant"), m_variant->currentData().toString());
    map.insert(QStringLiteral("axes"), m_axes->text().trimmed());
    settings.fromMap(map);
}

}  // namespace cambench
