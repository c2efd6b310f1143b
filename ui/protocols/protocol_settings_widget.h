#pragma once

#include "comm/device/protocol_settings.h"

#include <QHash>
#include <QWidget>

#include <functional>

namespace cambench {

// The part of the connection page that belongs to one protocol: its own
// settings beside the line's (as QGroundControl's LinkConfiguration pages
// are). A protocol without a widget has no settings of its own.
class ProtocolSettingsWidget : public QWidget {
    Q_OBJECT
public:
    using QWidget::QWidget;

    // Shows `settings`, which are of this widget's protocol.
    virtual void load(const comm::ProtocolSettings& settings) = 0;
    // Writes the values shown into `settings`.
    virtual void store(comm::ProtocolSettings& settings) const = 0;

Q_SIGNALS:
    // The widget offers a choice that is another protocol (the table
    // interface's variants): the page should switch to `protocolId`.
    void protocolRequested(const QString& protocolId);
};

// Which widget each protocol brings, by registry id. Filled by the GUI part
// of each family's FamilyParts (app/registry/<family>/), one line a protocol.
class ProtocolWidgetRegistry {
public:
    using Factory = std::function<ProtocolSettingsWidget*(const QString& protocolId)>;

    static ProtocolWidgetRegistry& instance();

    void add(const QString& protocolId, Factory factory);
    // A new widget for `protocolId`, or nullptr when it has none.
    ProtocolSettingsWidget* create(const QString& protocolId) const;

private:
    QHash<QString, Factory> m_factories;
};

}  // namespace cambench
