#pragma once

#include "model/camcon/dead_times.h"
#include "model/camcon/device_info.h"
#include "model/camcon/plc_network.h"
#include "model/camcon/project_file.h"
#include "model/camcon/system_settings.h"
#include "model/camcon/user.h"

#include <QList>
#include <QMap>

#include <QObject>
#include "model/camcon/dead_time_modes.h"
#include "model/camcon/carry_over.h"

#include <optional>

namespace cambench {

class CamDocument;
class TableSectionCopies;

// Where values that replace the workspace's come from. A device read also
// replaces the device copy; a file (a project) only the edited state.
enum class ValueSource { Device, File };

// Everything the user works on for one device, beside what the device holds
// (the copy last read from or written to it). Lives outside the main window,
// so a reconnect, a language switch (which rebuilds the window) or a failed
// read never loses an unwritten edit. Cam programs, names and dead times are
// in the cam editor's CamDocument; settings, users and PLC networks here.
//
// One rule for values that arrive (a read, an opened project): with
// `keepEdits`, an item the user edited keeps the edit and every other item
// takes the new value; without, every item takes it.
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
    // Forgets everything, edits and device copies (a new project).
    void clear(const DeviceInfo& info);

    // When each part of the device copy was read (UTC); empty: not read.
    const ProjectReadTimes& readTimes() const { return m_readAt; }
    void setReadTime(ProjectPart part, const QDateTime& utc);
    void setProgramReadTime(int program, const QDateTime& utc);
    // The newest time anything was read from the device (invalid: never).
    QDateTime lastReadTime() const;

    // --- Output names and dead times: edited and device copy in the CamDocument.
    bool outputSettingsKnown() const;
    qint32 deviceDeadTime(int output) const;
    QString deviceOutputName(int output) const;
    void mergeOutputSettings(const QMap<int, QString>& names, const DeadTimes& deadTimes,
                             ValueSource source, bool keepEdits);
    int outputSettingsEditCount() const;

    // --- Encoder & system settings (keys of settingSpecs())
    const SystemSettings& settings() const { return m_settings; }
    const SystemSettings& deviceSettings() const { return m_deviceSettings; }
    bool settingsKnown() const { return m_settingsKnown; }
    void mergeSettings(const SystemSettings& settings, ValueSource source, bool keepEdits);
    void setSetting(const QString& key, const QVariant& value);
    // After a write: the device holds these values now.
    void setDeviceSettings(const SystemSettings& values);
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
    bool usersKnown() const { return m_usersKnown; }
    void mergeUsers(const QList<User>& users, ValueSource source, bool keepEdits);
    void setUser(int index, const User& user);
    int addUser(const User& user);
    void removeUser(int index);
    bool userChanged(int index) const;
    QStringList deletedUserNumbers() const;
    const User* deviceUser(const QString& number) const;
    int userEditCount() const;
    // After a write: the device's user `deviceNumber` is now `actual` (or
    // gone, when empty); the edited user `index` (-1: a deletion) follows.
    void setDeviceUser(int index, const QString& deviceNumber, const std::optional<User>& actual);

    // --- PLC networks, key = plcKey(area, number)
    static int plcKey(int area, int number) { return (area << 8) | number; }
    const QMap<int, PlcNetwork>& plcNetworks() const { return m_plc; }
    const QMap<int, PlcNetwork>& devicePlcNetworks() const { return m_devicePlc; }
    PlcNetwork plcNetwork(int area, int number) const;
    void mergePlcNetworks(const QList<PlcNetwork>& networks, ValueSource source, bool keepEdits);
    void setPlcNetwork(const PlcNetwork& network);
    bool isPlcNetworkChanged(int key) const;
    QList<int> changedPlcNetworks() const;
    void setDevicePlcNetwork(const PlcNetwork& network);

    // --- Dead-time modes (table interface). The Dead-time modes page holds
    // the device's copy and the edits; the workspace holds the values as
    // edited, so that a project saves them, and passes modes that arrive
    // from a project file (or a read of everything) to the page.
    const DeadTimeModes& deadTimeModes() const { return m_deadTimeModes; }
    void takeDeadTimeModes(const DeadTimeModes& modes, bool fromDevice);
    // The page's values as edited and its copy of the device's.
    void noteDeadTimeModes(const DeadTimeModes& edited, const DeadTimeModes& onDevice);
    const DeadTimeModes& deviceDeadTimeModes() const { return m_deviceDeadTimeModes; }
    bool deadTimeModesEdited() const { return m_deadTimeModes != m_deviceDeadTimeModes; }
    // Outputs whose mode as edited differs from the device's copy (or whose
    // device value is not known).
    QList<int> changedDeadTimeModes() const;
    // After a write: the device holds `deadTime` for `output` now.
    void setDeviceDeadTimeMode(int output, const OutputDeadTime& deadTime);

    // --- Analogue cams, programming program, EEPROM lock (table interface).
    TableSectionCopies* tableSections() const { return m_tableSections; }

    // Every item that differs from the device, across all sections.
    int changedCount() const;

    // --- Which device the device copies are from: the identity and
    // fingerprint read last (on a connect, or with a read of everything).
    const std::optional<DeviceInfo>& copiesFrom() const { return m_copiesFrom; }
    // Whether the fingerprint in copiesFrom() is still the device's: a
    // write of ours changes the counts of programmed cams and dead times.
    bool copiesFingerprintKnown() const { return m_fingerprintKnown; }
    void setCopiesFrom(const DeviceInfo& identity);
    void fingerprintChangedByWrite() { m_fingerprintKnown = false; }
    // Whether a device that identified itself as `now` is the one the device
    // copies were read from (true when there are none to compare with).
    bool copiesAreFrom(const DeviceInfo& now) const;
    // Another device answers: every device copy and read time is forgotten
    // (see CamDocument::forgetDeviceCopies), and with them what was only
    // the old device's; of the edits, what `carry` says stays and counts as
    // not on the device, and a read of the new device keeps it over its
    // values without asking (takeIncoming). `note` says so until the next
    // read of everything.
    void forgetDeviceCopies(const QString& note, CarryOver carry);
    // A section the connected protocol lacks: its device copy is not this
    // device's state and is forgotten, edits stay.
    void forgetDeviceUsers(CarryOver carry = CarryOver::Changes);
    void forgetDeviceSettings(CarryOver carry = CarryOver::Changes);
    void forgetDevicePlcNetworks(CarryOver carry = CarryOver::Changes);
    // The table interface's sections (dead-time modes, analogue cams,
    // programming program, EEPROM lock) on a protocol without them.
    void forgetDeviceTableSections();
    // After another device answered: which device the edits were carried
    // from and how (nullopt: no device change, or nothing carried).
    struct CarriedFrom {
        DeviceInfo device;
        CarryOver carry = CarryOver::Changes;
    };
    const std::optional<CarriedFrom>& carriedFrom() const { return m_carriedFrom; }
    // Whether a section's values are yet to be read from the device since
    // edits were carried to it: such a read keeps them without asking.
    bool awaitsCarried(ProjectPart part) const;
    bool awaitsCarriedProgram(int program) const;
    QString otherDeviceNote() const { return m_otherDeviceNote; }
    void clearOtherDeviceNote();

Q_SIGNALS:
    void infoChanged();
    void projectPathChanged();
    void settingsChanged();
    void usersChanged();
    void plcChanged();
    void readTimesChanged();
    void changedCountChanged(int count);
    void otherDeviceNoteChanged();
    // Modes from a project file (edits for the page) or from the device.
    void deadTimeModesIncoming(const DeadTimeModes& modes, bool fromDevice);
    // Another device: the page forgets its copy and keeps `carried` as edits
    // for the new device's rows.
    void deadTimeModesForgotten(const DeadTimeModes& carried);

private:
    void notifyChanged();
    void forgetDeviceDeadTimeModes(CarryOver carry);
    DeadTimeModes m_deadTimeModes;
    DeadTimeModes m_deviceDeadTimeModes;
    QString deviceNumberFor(const User& user) const;
    void mergeUsersFromFile(const QList<User>& users, bool keepEdits);

    DeviceInfo m_info;
    QString m_projectPath;
    bool m_infoFromDevice = false;
    CamDocument* m_cams;
    TableSectionCopies* m_tableSections;
    ProjectReadTimes m_readAt;
    SystemSettings m_settings;
    SystemSettings m_deviceSettings;
    bool m_settingsKnown = false;
    QList<EditedUser> m_users;
    QList<User> m_deviceUsers;
    bool m_usersKnown = false;
    QMap<int, PlcNetwork> m_plc;
    QMap<int, PlcNetwork> m_devicePlc;
    int m_lastCount = 0;
    std::optional<DeviceInfo> m_copiesFrom;
    bool m_fingerprintKnown = false;
    QString m_otherDeviceNote;
    std::optional<CarriedFrom> m_carriedFrom;
};

}  // namespace cambench
