#pragma once

#include "model/camcon/system_settings.h"

#include <QStringList>

#include <optional>

class QWidget;

namespace cambench {

// Issue 39: the communication settings (protocol, device number) among
// the values a write is about to send, with the device's values where
// known; only those that differ. Empty: nothing to ask.
SystemSettings linkSettingsToAsk(const SystemSettings& wanted, const SystemSettings& onDevice);

// Asks, before the write, whether those settings go to the device too,
// saying that the next connection will need them; unticked (the default)
// they are left out and the rest is written. nullopt: the person cancelled
// the write; otherwise the keys to write (WritePlan::linkSettingsAsked).
std::optional<QStringList> askLinkSettings(QWidget* parent, const SystemSettings& link,
                                           const SystemSettings& onDevice);

}  // namespace cambench
