#pragma once

#include "model/camcon/dead_times.h"
#include "model/camcon/device_info.h"
#include "model/camcon/plc_network.h"
#include "model/camcon/system_settings.h"
#include "model/camcon/user.h"

#include <QList>
#include <QMap>
#include <QObject>

namespace cambench {

class CamDocument;

// Everything the user works on for one device, beside what the device holds
// (the copy last read from or written to it). Lives outside the main window,
// so a reconnect, a language switch (which rebuilds the window) or a failed
// read never loses an unwritten edit. Cam programs, names and dead times are
// in the cam editor's CamDocument; settings, users and PLC networks here.
class Workspace : public QObject {
    Q_OBJECT
public:
    explicit Workspace(QObject* parent = nullptr);
    ~Workspace() override;

    const DeviceInfo& info() const { return m_info; }
    bool infoFromDevice() const { return m_infoFromDevice; }
    // Capacities for the editors: from the device, or chosen for a project.
    void setInfo(const DeviceInfo& info, bool fromDevice);

    CamDocument* cams() const { return m_cams; }

    // The project file this work was last opened from or saved to (empty:
    // none). Kept here, not in the window, so a language switch keeps it.
    QString projectPath() const { return m_projectPath; }
    void setProjectPath(const QString& path);

    // --- Output names and dead times: edited in the CamDocument; the device
    // copy is mirrored here per output so a partly failed write keeps exactly
    // the failed items marked as edited.
    bool outputSettingsKnown() const { return m_outputSettingsKnown; }
    qint32 deviceDeadTime(int output) const { return m_deviceDeadTimes.value(output); }
    QString deviceOutputName(int output) const { return m_deviceOutputNames.value(output); }
    void loadOutputSettingsFromDevice(const QMap<int, QString>& names, const DeadTimes& deadTimes);
    // After a write: these outputs' dead times / names now match the device.
    void markOutputSettingsWritten(const QList<int>& deadTimes, const QList<int>& names);

    // --- Encoder & system settings (keys of settingSpecs())
    const SystemSettings& settings() const { return m_settings; }
    const SystemSettings& deviceSettings() const { return m_deviceSettings; }
    bool settingsKnown() const { return m_settingsKnown; }
    void loadSettingsFromDevice(const SystemSettings& settings);
    void loadSettingsOffline(const SystemSettings& settings);
    void setSetting(const QString& key, const QVariant& value);
    void markSettingsWritten(const QStringList& keys);
    QStringList changedSettings() const;

    // --- Users. Each edited user remembers the number it has on the device
    // (empty for a user not yet written); a device user without an edited
    // counterpart is to be deleted.
    struct EditedUser {
        User user;
        QString deviceNumber;
    };
    const QList<EditedUser>& users() const { return m_users; }
    const QList<User>& deviceUsers() const { return m_deviceUsers; }
    void loadUsersFromDevice(const QList<User>& users);
    void loadUsersOffline(const QList<User>& users);
    void setUser(int index, const User& user);
    int addUser(const User& user);
    void removeUser(int index);
    bool userChanged(int index) const;
    QStringList deletedUserNumbers() const;
    // After a successful write of user `index` / a delete of `number`.
    void markUserWritten(int index);
    void markUserDeleted(const QString& number);

    // --- PLC networks, key = plcKey(area, number)
    static int plcKey(int area, int number) { return (area << 8) | number; }
    const QMap<int, PlcNetwork>& plcNetworks() const { return m_plc; }
    const QMap<int, PlcNetwork>& devicePlcNetworks() const { return m_devicePlc; }
    PlcNetwork plcNetwork(int area, int number) const;
    void loadPlcFromDevice(const PlcNetwork& network);
    void setPlcNetwork(const PlcNetwork& network);
    bool isPlcNetworkChanged(int key) const;
    QList<int> changedPlcNetworks() const;
    void markPlcWritten(int key);

    // Every item that differs from the device, across all sections.
    int changedCount() const;

Q_SIGNALS:
    void infoChanged();
    void projectPathChanged();
    void settingsChanged();
    void usersChanged();
    void plcChanged();
    void changedCountChanged(int count);

private:
    void notifyChanged();

    DeviceInfo m_info;
    QString m_projectPath;
    bool m_infoFromDevice = false;
    CamDocument* m_cams;
    bool m_outputSettingsKnown = false;
    DeadTimes m_deviceDeadTimes;
    QMap<int, QString> m_deviceOutputNames;
    SystemSettings m_settings;
    SystemSettings m_deviceSettings;
    bool m_settingsKnown = false;
    QList<EditedUser> m_users;
    QList<User> m_deviceUsers;
    QMap<int, PlcNetwork> m_plc;
    QMap<int, PlcNetwork> m_devicePlc;
    int m_lastCount = 0;
};

}  // namespace cambench
