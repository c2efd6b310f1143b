#pragma once

#include "comm/device/connection_settings.h"
#include "comm/device/protocol_settings.h"

#include <QByteArray>
#include <QStringList>

#include <optional>

class QMainWindow;

namespace cambench {

// What the GUI remembers between runs (QSettings, organisation "CamBench"):
// the last connection that worked, window layout, language, palette and
// the recent projects. Tests point QSettings at a temporary directory.
namespace guisettings {

struct RememberedConnection {
    comm::ConnectionSettings connection;
    comm::ProtocolSettingsPtr protocol;  // never null
};

// Saved when a connection is established, not when merely tried.
void saveConnection(const comm::ConnectionSettings& connection,
                    const comm::ProtocolSettings& protocol);
// Empty when nothing is remembered or the protocol is unknown now.
std::optional<RememberedConnection> loadConnection();

void saveWindow(const QMainWindow& window, int section);
// The section shown last, or -1; geometry and dock/toolbar state restored.
int restoreWindow(QMainWindow& window);

QString language();  // empty: not chosen yet
void setLanguage(const QString& language);
std::optional<bool> dark();
void setDark(bool dark);

constexpr int kMaxRecentProjects = 8;
QStringList recentProjects();
// Moves `path` to the front (absolute path), drops the oldest past the limit.
void addRecentProject(const QString& path);
void removeRecentProject(const QString& path);

}  // namespace guisettings
}  // namespace cambench
