#include "setting_field.h"

#include "ui/change_marker.h"
#include "ui/wheel_guard.h"

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

QString settingsText(const char* text) {
    return QCoreApplication::translate("Settings", text);
}

double scale(const SettingSpec& spec) {
    return std::pow(10.0, spec.decimals);
}

bool fitsInt(const SettingSpec& spec) {
    return spec.min >= std::numeric_limits<int>::min() &&
           spec.max <= std::numeric_limits<int>::max();
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
    guardWheel(m_editor);
}

QString SettingField::textWithUnit(const SettingSpec& spec, const QVariant& value) {
    if (spec.kind == SettingKind::Integer && qstrcmp(spec.unit, "0.1 ms") == 0) {
        bool number = false;
        const double tenths = value.toDouble(&number);
        if (number) return tr("%1 ms").arg(QLocale().toString(tenths / 10.0, 'f', 1));
    }
    const QString shown = displayText(spec, value);
    return *spec.unit ? shown + QLatin1Char(' ') + settingsText(spec.unit) : shown;
}

QString SettingField::labelText(const SettingSpec& spec) {
    return settingsText(spec.label);
}

QString SettingField::rangeText(const SettingSpec& spec) {
    const QString unit = *spec.unit ? QLatin1Char(' ') + settingsText(spec.unit) : QString();
    switch (spec.kind) {
        case SettingKind::Integer:
            if (spec.step > 1)
                return SettingField::tr("%1 … %2%3, steps of %4")
                    .arg(spec.min)
                    .arg(spec.max)
                    .arg(unit)
                    .arg(spec.step);
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
    if (*spec.section)
        tip += QLatin1Char('\n') +
               SettingField::tr("Manual section %1").arg(QLatin1String(spec.section));
    if (spec.readOnly)
        tip += QLatin1Char('\n') + SettingField::tr("Read only: shown as the device reports it.");
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
            return value.toLongLong() == 0 ? SettingField::tr("none")
                                           : QString::number(value.toLongLong());
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
                combo->addItem(settingsText(choice.label),
                               QVariant::fromValue<qint64>(choice.value));
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
    if (auto* spin = qobject_cast<QSpinBox*>(m_editor))
        return QVariant::fromValue<qint64>(spin->value());
    if (auto* spin = qobject_cast<QDoubleSpinBox*>(m_editor)) {
        return QVariant::fromValue<qint64>(std::llround(spin->value() * scale(m_spec)));
    }
    return {};
}

void SettingField::fitRange(const QVariant& shown) {
    qint64 low = m_spec.min;
    qint64 high = m_spec.max;
    qsizetype length = m_spec.maxLength;
    for (const QVariant& value : {shown, m_deviceKnown ? m_device : QVariant()}) {
        if (!value.isValid()) continue;
        low = std::min(low, value.toLongLong());
        high = std::max(high, value.toLongLong());
        length = std::max(length, value.toString().size());
    }
    if (isReference(m_spec)) low = std::min<qint64>(low, 0);  // 0 = none
    if (auto* spin = qobject_cast<QSpinBox*>(m_editor)) {
        spin->setRange(int(std::max<qint64>(low, std::numeric_limits<int>::min())),
                       int(std::min<qint64>(high, std::numeric_limits<int>::max())));
    } else if (auto* spin = qobject_cast<QDoubleSpinBox*>(m_editor)) {
        spin->setRange(low / scale(m_spec), high / scale(m_spec));
    } else if (auto* edit = qobject_cast<QLineEdit*>(m_editor)) {
        // A longer text from the device is shown whole, not cut.
        if (m_spec.maxLength > 0) edit->setMaxLength(int(length));
    }
}

void SettingField::setValue(const QVariant& value) {
    m_updating = true;
    fitRange(value);
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
    updateMarks();
}

void SettingField::setDeviceValue(const QVariant& device, bool known) {
    m_device = device;
    m_deviceKnown = known;
    m_updating = true;
    fitRange(value());  // going back to the device's value stays possible
    m_updating = false;
    updateMarks();
}

void SettingField::updateMarks() {
    const QVariant shown = value();
    m_changed = !m_deviceKnown || m_device != shown;
    m_problem =
        shown.isValid() && !m_spec.readOnly ? settingValueProblem(m_spec, shown) : QString();
    QString prefix = m_changed ? changedMarker() : QString();
    if (!m_problem.isEmpty()) prefix += QStringLiteral("⚠ ");
    m_label->setText(prefix + labelText(m_spec));
    m_label->setFont(m_changed ? changedFont(m_label->font()) : QFont());
    QPalette pal =
        m_label->parentWidget() ? m_label->parentWidget()->palette() : m_label->palette();
    if (!m_problem.isEmpty()) pal.setColor(QPalette::WindowText, QColor(0xd0, 0x40, 0x2e));
    m_label->setPalette(pal);
    QString tip = toolTipText(m_spec);
    if (!m_problem.isEmpty()) {
        tip +=
            QLatin1Char('\n') +
            (m_changed ? SettingField::tr("Not allowed: %1.").arg(m_problem)
                       : SettingField::tr("The device holds a value outside the allowed range: %1. "
                                          "It is shown as the device has it, not changed.")
                             .arg(m_problem));
    }
    if (m_changed)
        tip += QLatin1Char('\n') + SettingField::tr("On the device: %1")
                                       .arg(m_deviceKnown ? displayText(m_spec, m_device)
                                                          : SettingField::tr("not read"));
    m_editor->setToolTip(tip);
    m_label->setToolTip(tip);
}

void SettingField::emitEdited() {
    if (m_updating) return;
    Q_EMIT valueEdited(QString::fromLatin1(m_spec.key), value());
    updateMarks();
}

}  // namespace cambench
