#pragma once

#include "model/camcon/system_settings.h"

#include <QObject>
#include <QVariant>

class QLabel;
class QWidget;

namespace cambench {

// One editor of the settings form, made from a SettingSpec: a spin box with
// the manual's range, a combo box with readable names, a line edit with the
// device's maximum length. Knows its label so it can mark a change.
class SettingField : public QObject {
    Q_OBJECT
public:
    SettingField(const SettingSpec& spec, QObject* parent = nullptr);

    const SettingSpec& spec() const { return m_spec; }
    QWidget* editor() const { return m_editor; }
    QLabel* label() const { return m_label; }
    QLabel* rangeLabel() const { return m_range; }

    QVariant value() const;
    // Shows `value` exactly, also outside the manual's range (the editor's
    // range widens to hold it, and the field is flagged); no valueEdited.
    void setValue(const QVariant& value);
    // Marks the field as differing from the device (or clears the mark).
    void setDeviceValue(const QVariant& device, bool known);
    // Why the shown value is not one the manual allows (empty when it is).
    QString problem() const { return m_problem; }
    bool isMarkedChanged() const { return m_changed; }

    // Texts of a value for comparisons and the report.
    static QString displayText(const SettingSpec& spec, const QVariant& value);
    // displayText() with the unit, as a report prints it; a count of
    // "0.1 ms" steps is shown in milliseconds ("12.5 ms", not "125 0.1 ms").
    static QString textWithUnit(const SettingSpec& spec, const QVariant& value);
    static QString labelText(const SettingSpec& spec);
    static QString rangeText(const SettingSpec& spec);
    static QString toolTipText(const SettingSpec& spec);

Q_SIGNALS:
    void valueEdited(const QString& key, const QVariant& value);

private:
    void createEditor();
    void emitEdited();
    // The editor's limits: the manual's range, widened to hold `value`.
    void fitRange(const QVariant& value);
    void updateMarks();

    const SettingSpec& m_spec;
    QWidget* m_editor = nullptr;
    QLabel* m_label = nullptr;
    QLabel* m_range = nullptr;
    bool m_updating = false;
    QVariant m_device;
    bool m_deviceKnown = false;
    bool m_changed = false;
    QString m_problem;
};

}  // namespace cambench
