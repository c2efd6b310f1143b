#include "gui_registry.h"

#include "ui/camcon/cambus/cambus_settings_widget.h"
#include "ui/camcon/camcon_gui.h"
#include "ui/camcon/protocols/ascii_settings_widget.h"
#include "ui/camcon/protocols/table_settings_widget.h"
#include "ui/compax3/compax3_gui.h"
#include "ui/compax3/protocols/compax3_settings_widget.h"
#include "ui/mc1/mc1_gui.h"
#include "ui/mc1/protocols/mc1_settings_widget.h"

namespace cambench {

void registerGuiParts() {
    ProtocolWidgetRegistry& widgets = ProtocolWidgetRegistry::instance();
    widgets.add(QStringLiteral("standard"),
                [](const QString&) { return new AsciiSettingsWidget(false); });
    widgets.add(QStringLiteral("multiuser"),
                [](const QString&) { return new AsciiSettingsWidget(true); });
    widgets.add(QStringLiteral("cambus"), [](const QString&) { return new CamBusSettingsWidget; });
    for (const char* id : {"3964r-n96", "3964r-e38"}) {
        widgets.add(QLatin1String(id),
                    [](const QString& protocol) { return new TableSettingsWidget(protocol); });
    }

    widgets.add(QStringLiteral("mc1"), [](const QString&) { return new Mc1SettingsWidget; });
    widgets.add(QStringLiteral("compax3"),
                [](const QString&) { return new Compax3SettingsWidget(false); });
    widgets.add(QStringLiteral("compax3-rs485"),
                [](const QString&) { return new Compax3SettingsWidget(true); });

    FamilyGuiRegistry& families = FamilyGuiRegistry::instance();
    families.add({QStringLiteral("camcon"), [](DeviceSession* session, QObject* parent) {
                      return new CamConGui(session, parent);
                  }});
    families.add({QStringLiteral("mc1"), [](DeviceSession* session, QObject* parent) {
                      return new Mc1Gui(session, parent);
                  }});
    families.add({QStringLiteral("compax3"), [](DeviceSession* session, QObject* parent) {
                      return new Compax3Gui(session, parent);
                  }});
}

}  // namespace cambench
