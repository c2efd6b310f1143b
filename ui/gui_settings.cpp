#include "gui_settings.h"

#include "comm/device/protocol_registry.h"

#include <QFileInfo>
#include <QMainWindow>
#include <QSettings>

namespace cambench::guisettings {

namespace {
const QString kPort = QStringLiteral("connection/port");
const QString kProtocol = QStringLiteral("connection/protocol");
const QString kSerial = QStringLiteral("connection/serial");
const QString kProtocolSettings = QStringLiteral("connection/protocolSettings");
const QString kGeometry = QStringLiteral("window/geometry");
const QString kState = QStringLiteral("window/state");
const QString kSection = QStringLiteral("window/section");
const QString kLanguage = QStringLiteral("ui/language");
const QString kDark = QStringLiteral("ui/dark");
const QString kRecent = QStringLiteral("recent/projects");

QVariantMap serialToMap(const comm::SerialSettings& serial) {
    return {{QStringLiteral("baud"), serial.baud},
            {QStringLiteral("dataBits"), serial.dataBits},
            {QStringLiteral("parity"), QString(QLatin1Char(serial.parity))},
            {QStringLiteral("stopBits"), serial.stopBits},
            {QStringLiteral("flowControl"), QString(QLatin1Char(serial.flowControl))}};
}

comm::SerialSettings serialFromMap(const QVariantMap& map, comm::SerialSettings serial) {
    const auto letter = [&map](const char* key, char fallback) {
        const QString text = map.value(QLatin1String(key)).toString();
        return text.size() == 1 ? text.at(0).toLatin1() : fallback;
    };
    serial.baud = map.value(QStringLiteral("baud"), serial.baud).toInt();
    serial.dataBits = map.value(QStringLiteral("dataBits"), serial.dataBits).toInt();
    serial.parity = letter("parity", serial.parity);
    serial.stopBits = map.value(QStringLiteral("stopBits"), serial.stopBits).toInt();
    serial.flowControl = letter("flowControl", serial.flowControl);
    return serial;
}
}  // namespace

void saveConnection(const comm::ConnectionSettings& connection,
                    const comm::ProtocolSettings& protocol) {
    QSettings settings;
    settings.setValue(kPort, connection.port);
    settings.setValue(kProtocol, protocol.protocolId());
    settings.setValue(kSerial, serialToMap(connection.serial));
    settings.setValue(kProtocolSettings, protocol.toMap());
}

std::optional<RememberedConnection> loadConnection() {
    const QSettings settings;
    const QString port = settings.value(kPort).toString();
    if (port.isEmpty()) return std::nullopt;
    const comm::ProtocolInfo* info =
        comm::ProtocolRegistry::instance().find(settings.value(kProtocol).toString());
    if (!info) info = comm::ProtocolRegistry::instance().all().value(0);
    if (!info) return std::nullopt;
    RememberedConnection remembered;
    remembered.connection.port = port;
    remembered.connection.protocol = info->id;
    remembered.connection.serial =
        serialFromMap(settings.value(kSerial).toMap(), info->defaultSerial);
    std::unique_ptr<comm::ProtocolSettings> protocol = info->makeSettings();
    protocol->fromMap(settings.value(kProtocolSettings).toMap());
    remembered.protocol = std::move(protocol);
    return remembered;
}

void saveWindow(const QMainWindow& window, int section) {
    QSettings settings;
    settings.setValue(kGeometry, window.saveGeometry());
    settings.setValue(kState, window.saveState());
    settings.setValue(kSection, section);
}

int restoreWindow(QMainWindow& window) {
    const QSettings settings;
    if (settings.contains(kGeometry))
        window.restoreGeometry(settings.value(kGeometry).toByteArray());
    if (settings.contains(kState)) window.restoreState(settings.value(kState).toByteArray());
    return settings.value(kSection, -1).toInt();
}

QString language() {
    return QSettings().value(kLanguage).toString();
}

void setLanguage(const QString& language) {
    QSettings().setValue(kLanguage, language);
}

std::optional<bool> dark() {
    const QSettings settings;
    if (!settings.contains(kDark)) return std::nullopt;
    return settings.value(kDark).toBool();
}

void setDark(bool dark) {
    QSettings().setValue(kDark, dark);
}

QStringList recentProjects() {
    return QSettings().value(kRecent).toStringList();
}

void addRecentProject(const QString& path) {
    const QString absolute = QFileInfo(path).absoluteFilePath();
    QStringList recent = recentProjects();
    recent.removeAll(absolute);
    recent.prepend(absolute);
    while (recent.size() > kMaxRecentProjects) recent.removeLast();
    QSettings().setValue(kRecent, recent);
}

void removeRecentProject(const QString& path) {
    QStringList recent = recentProjects();
    recent.removeAll(QFileInfo(path).absoluteFilePath());
    QSettings().setValue(kRecent, recent);
}

}  // namespace cambench::guisettings
