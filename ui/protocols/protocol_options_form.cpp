#include "protocol_options_form.h"

#include "comm/device/protocol_registry.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>

namespace cambench {

namespace {

// The declarations are English, marked for the "cambench::comm" context.
QString translated(const QString& text) {
    return QCoreApplication::translate("cambench::comm", text.toUtf8().constData());
}

// "The number of the CamCon to talk to on the bus (0–63)."
QString tooltipOf(const comm::ProtocolOption& option) {
    QString help = translated(option.help);
    if (!help.isEmpty()) help[0] = help.at(0).toUpper();
    if (option.isChoice()) return help + u'.';
    return QStringLiteral("%1 (%2–%3).").arg(help).arg(option.min).arg(option.max);
}

}  // namespace

ProtocolOptionsForm::ProtocolOptionsForm(const comm::ProtocolInfo& protocol, QWidget* parent)
    : ProtocolSettingsWidget(parent), m_form(new QFormLayout(this)) {
    m_form->setContentsMargins(0, 0, 0, 0);
    for (const comm::ProtocolOption& option : protocol.options) {
        QWidget* field = nullptr;
        if (option.isChoice()) {
            auto* choice = new QComboBox;
            for (const QString& word : option.choices) choice->addItem(word, word);
            m_choices.insert(option.settingsKey, choice);
            field = choice;
        } else {
            auto* number = new QSpinBox;
            number->setRange(option.min, option.max);
            number->setValue(option.fallback);
            m_numbers.insert(option.settingsKey, number);
            field = number;
        }
        field->setObjectName(QStringLiteral("option-") + option.name);
        field->setToolTip(tooltipOf(option));
        m_keyOfName.insert(option.name, option.settingsKey);
        m_form->addRow(translated(option.label), field);
    }
    if (!protocol.note.isEmpty()) {
        auto* note = new QLabel(translated(protocol.note));
        note->setWordWrap(true);
        m_form->addRow(note);
    }
}

QSpinBox* ProtocolOptionsForm::numberField(const QString& name) const {
    return m_numbers.value(m_keyOfName.value(name));
}

void ProtocolOptionsForm::load(const comm::ProtocolSettings& settings) {
    const QVariantMap map = settings.toMap();
    for (auto it = m_numbers.cbegin(); it != m_numbers.cend(); ++it)
        (*it)->setValue(map.value(it.key(), (*it)->value()).toInt());
    for (auto it = m_choices.cbegin(); it != m_choices.cend(); ++it)
        (*it)->setCurrentIndex(qMax(0, (*it)->findData(map.value(it.key()))));
}

void ProtocolOptionsForm::store(comm::ProtocolSettings& settings) const {
    QVariantMap map = settings.toMap();
    for (auto it = m_numbers.cbegin(); it != m_numbers.cend(); ++it)
        map.insert(it.key(), (*it)->value());
    for (auto it = m_choices.cbegin(); it != m_choices.cend(); ++it)
        map.insert(it.key(), (*it)->currentData());
    settings.fromMap(map);
}

}  // namespace cambench
