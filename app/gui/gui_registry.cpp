#include "gui_registry.h"

#include "ui/camcon/protocols/ascii_settings_widget.h"
#include "ui/camcon/protocols/table_settings_widget.h"

namespace cambench {

void registerProtocolWidgets() {
    ProtocolWidgetRegistry& widgets = ProtocolWidgetRegistry::instance();
    widgets.add(QStringLiteral("standard"),
                [](const QString&) { return new AsciiSettingsWidget(false); });
    widgets.add(QStringLiteral("multiuser"),
                [](const QString&) { return new AsciiSettingsWidget(true); });
    for (const char* id : {"3964r-n96", "3964r-e38"}) {
        widgets.add(QLatin1String(id),
                    [](const QString& protocol) { return new TableSettingsWidget(protocol); });
    }
}

}  // namespace cambench
