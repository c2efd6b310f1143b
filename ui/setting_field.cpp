#include "setting_field.h"

#include "change_marker.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QSpinBox>

#include <cmath>
#include <limits>

namespace cambench {

namespace {

QString settingsText(const char* text) { return QCoreApplication::translate("Settings", text); }

double scale(const SettingSpec& spec) { return std::pow(10.0, spec.decimals); }

bool fitsInt(const SettingSpec& spec) {
    return spec.min >= std::numeric_limits<int>::min() && spec.max <= std::numeric_limits<int>::max();
}

bool isReference(const SettingSpec& spec) {
    return spec.kind == SettingKind::OutputRef || spec.kind == SettingKind::InputRef;
}

}  // namespace

SettingField::SettingField(const SettingSpec& spec, QObject* parent)
    : QObject(parent), m_spec(spec) {
    m_label = new QLabel(labelText(spec));
    m_range = new QLabel(rangeText(spec));
    m_range->setForegroundRole(QPalette::PlaceholderText);
    createEditor();
    const QString tip = toolTipText(spec);
    m_label->setToolTip(tip);
    m_editor->setToolTip(tip);
    m_label->setBuddy(m_editor);
    m_editor->setEnabled(!spec.readOnly);
    m_editor->setObjectName(QString::fromLatin1(spec.key));
}

QString SettingField::labelText(const SettingSpec& spec) { return settingsText(spec.label); }

QString SettingField::rangeText(const SettingSpec& spec) {
    const QString unit = *spec.unit ? QLatin1Char(' ') + settingsText(spec.unit) : QString();
    switch (spec.kind) {
        case SettingKind::Integer:
            if (spec.step > 1)
                return SettingField::tr("%1 … %2%3, steps of %4").arg(spec.min).arg(spec.max).arg(unit).arg(spec.step);
            return SettingField::tr("%1 … %2%3").arg(spec.min).arg(spec.max).arg(unit);
        case SettingKind::Fixed: {
            const QLocale locale;
            return SettingField::tr("%1 … %2%3")
                .arg(locale.toString(spec.min / scale(spec), 'f', spec.decimals),
                     locale.toString(spec.max / scale(spec), 'f', spec.decimals), unit);
        }
        case SettingKind::OutputRef:
            return SettingField::tr("output 1 … %1, 0 = none").arg(spec.max);
        case SettingKind::InputRef:
            return SettingField::tr("input 1 … %1, 0 = none").arg(spec.max);
        case SettingKind::Text:
            return SettingField::tr("up to %n character(s)", nullptr, spec.maxLength);
        case SettingKind::Enum:
            return {};
    }
    return {};
}

QString SettingField::toolTipText(const SettingSpec& spec) {
    QString tip = settingsText(spec.tooltip);
    const QString range = rangeText(spec);
    if (!range.isEmpty()) tip += QLatin1Char('\n') + SettingField::tr("Range: %1").arg(range);
    if (*spec.section) tip += QLatin1Char('\n') + SettingField::tr("Manual section %1").arg(QLatin1String(spec.section));
    if (spec.readOnly) tip += QLatin1Char('\n') + SettingField::tr("Read only: shown as the device reports it.");
    return tip;
}

QString SettingField::displayText(const SettingSpec& spec, const QVariant& value) {
    if (!value.isValid()) return SettingField::tr("(not set)");
    switch (spec.kind) {
        case SettingKind::Enum:
            for (const SettingChoice& choice : spec.choices) {
                if (choice.value == value.toLongLong()) return settingsText(choice.label);
            }
            return QString::number(value.toLongLong());
        case SettingKind::OutputRef:
        case SettingKind::InputRef:
            return value.toLongLong() == 0 ? SettingField::tr("none") : QString::number(value.toLongLong());
        case SettingKind::Fixed:
            return QLocale().toString(value.toLongLong() / scale(spec), 'f', spec.decimals);
        case SettingKind::Text:
            return value.toString();
        case SettingKind::Integer:
            return QString::number(value.toLongLong());
    }
    return value.toString();
}

void SettingField::createEditor() {
    switch (m_spec.kind) {
        case SettingKind::Enum: {
            auto* combo = new QComboBox;
            for (const SettingChoice& choice : m_spec.choices)
                combo->addItem(settingsText(choice.label), QVariant::fromValue<qint64>(choice.value));
            connect(combo, &QComboBox::currentIndexChanged, this, &SettingField::emitEdited);
            m_editor = combo;
            return;
        }
        case SettingKind::Text: {
            auto* edit = new QLineEdit;
            if (m_spec.maxLength > 0) edit->setMaxLength(m_spec.maxLength);
            connect(edit, &QLineEdit::textEdited, this, &SettingField::emitEdited);
            m_editor = edit;
            return;
        }
        case SettingKind::Fixed: {
            auto* spin = new QDoubleSpinBox;
            spin->setDecimals(m_spec.decimals);
            spin->setRange(m_spec.min / scale(m_spec), m_spec.max / scale(m_spec));
            spin->setSingleStep(1.0 / scale(m_spec));
            connect(spin, &QDoubleSpinBox::valueChanged, this, &SettingField::emitEdited);
            m_editor = spin;
            return;
        }
        case SettingKind::Integer:
        case SettingKind::OutputRef:
        case SettingKind::InputRef:
            break;
    }
    if (!fitsInt(m_spec)) {
        // 32-bit unsigned ranges do not fit a QSpinBox.
        auto* spin = new QDoubleSpinBox;
        spin->setDecimals(0);
        spin->setRange(double(m_spec.min), double(m_spec.max));
        spin->setSingleStep(m_spec.step);
        connect(spin, &QDoubleSpinBox::valueChanged, this, &SettingField::emitEdited);
        m_editor = spin;
        return;
    }
    auto* spin = new QSpinBox;
    spin->setRange(int(m_spec.min), int(m_spec.max));
    spin->setSingleStep(std::max(1, m_spec.step));
    if (isReference(m_spec)) {
        spin->setMinimum(0);
        spin->setSpecialValueText(SettingField::tr("none"));
    }
    connect(spin, &QSpinBox::valueChanged, this, &SettingField::emitEdited);
    m_editor = spin;
}

QVariant SettingField::value() const {
    if (auto* combo = qobject_cast<QComboBox*>(m_editor)) return combo->currentData();
    if (auto* edit = qobject_cast<QLineEdit*>(m_editor)) return edit->text();
    if (auto* spin = qobject_cast<QSpinBox*>(m_editor)) return QVariant::fromValue<qint64>(spin->value());
    if (auto* spin = qobject_cast<QDoubleSpinBox*>(m_editor)) {
        return QVariant::fromValue<qint64>(std::llround(spin->value() * scale(m_spec)));
    }
    return {};
}

void SettingField::setValue(const QVariant& value) {
    m_updating = true;
    if (auto* combo = qobject_cast<QComboBox*>(m_editor)) {
        int index = combo->findData(QVariant::fromValue<qint64>(value.toLongLong()));
        if (index < 0 && value.isValid()) {
            // A value the table does not name still has to be shown.
            combo->addItem(SettingField::tr("unknown (%1)").arg(value.toLongLong()),
                           QVariant::fromValue<qint64>(value.toLongLong()));
            index = combo->count() - 1;
        }
        combo->setCurrentIndex(index);
    } else if (auto* edit = qobject_cast<QLineEdit*>(m_editor)) {
        edit->setText(value.toString());
    } else if (auto* spin = qobject_cast<QSpinBox*>(m_editor)) {
        spin->setValue(int(value.toLongLong()));
    } else if (auto* spin = qobject_cast<QDoubleSpinBox*>(m_editor)) {
        spin->setValue(value.toLongLong() / scale(m_spec));
    }
    m_updating = false;
}

void SettingField::setDeviceValue(const QVariant& device, bool known) {
    const bool changed = !known || device != value();
    m_label->setText((changed ? changedMarker() : QString()) + labelText(m_spec));
    m_label->setFont(changed ? changedFont(m_label->font()) : QFont());
    const QString tip = toolTipText(m_spec);
    m_editor->setToolTip(changed ? tip + QLatin1Char('\n') +
                                       SettingField::tr("On the device: %1").arg(known ? displayText(m_spec, device)
                                                                            : SettingField::tr("not read"))
                                 : tip);
}

void SettingField::emitEdited() {
    if (!m_updating) Q_EMIT valueEdited(QString::fromLatin1(m_spec.key), value());
}

}  // namespace cambench
