#pragma once

#include "system_settings.h"

#include <QString>
#include <QStringList>

namespace cambench {

// The CamCon's communication settings in the settings model: how the
// device is reached (manual 5.4.3: ?GSIO the protocol, ?GNR the device
// number on a Multiuser or Cam-BUS line; table interface area 205 words 11
// and 0). Written, they change the next connection (a device set to 3964R
// no longer answers Standard), so a write sends them only when a person
// names them (usecases::WritePlan::linkSettingsAsked). The table
// interface's CP type and Profibus address (area 205 words 7 and 8) are no
// settings of the model: no project or settings file carries them.

// In the order a write sends them: the device number first (on a
// point-to-point protocol it changes nothing of the connection; on a bus
// the connection follows it), the protocol last (after it nothing reaches
// the device over this connection).
const QStringList& linkSettingKeys();
bool isLinkSetting(const QString& key);

// "Communication protocol 3964R, Device number 5" for the keys of
// `settings` that are communication settings.
QString linkSettingsText(const SystemSettings& settings);

}  // namespace cambench
