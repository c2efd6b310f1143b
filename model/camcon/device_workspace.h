#pragma once

#include "model/camcon/analogue_cams.h"
#include "model/camcon/cam_section.h"
#include "model/camcon/dead_time_modes.h"
#include "model/camcon/dead_times.h"
#include "model/camcon/device_info.h"
#include "model/camcon/plc_network.h"
#include "model/camcon/programming_program.h"
#include "model/camcon/project_file.h"
#include "model/camcon/section_copies.h"
#include "model/camcon/system_settings.h"
#include "model/camcon/user_copies.h"

#include <QList>
#include <QMap>
#include <QObject>

#include <optional>

namespace cambench {

// Everything the user works on for one device, beside what the device holds
// (the copy last read from or written to it). Lives outside the main window,
// so a reconnect, a language switch (which rebuilds the window) or a failed
// read never loses an unwritten edit. Settings, users, PLC networks and the
// table interface's sections are held here; cam programs, names and dead
// times in the cam section attached by the GUI (attachCams: the cam
// editor's document, ui/camcon/workspace.h); without one they count as
// nothing changed.
//
// One rule for values that arrive (a read, an opened project): with
// `keepEdits`, an item the user edited keeps the edit and every other item
// takes the new value; without, every item takes it (SectionCopies::merge).
class DeviceWorkspace : public QObject {
    Q_OBJECT
public:
    explicit DeviceWorkspace(QObject* parent = nullptr);
    ~DeviceWorkspace() override;

    const DeviceInfo& info() const { return m_info; }
    bool infoFromDevice() const { return m_infoFromDevice; }
    // Capacities for the editors: from the device, or chosen for a project.
    void setInfo(const DeviceInfo& info, bool fromDevice);

    // The cam programs, names and dead times (nullptr: none attached).
    CamSection* camSection() const { return m_camSection; }

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

    // --- Output names and dead times: edited and device copy in the cam section.
    bool outputSettingsKnown() const;
    qint32 deviceDeadTime(int output) const;
    QString deviceOutputName(int output) const;
    void mergeOutputSettings(const QMap<int, QString>& names, const DeadTimes& deadTimes,
                             ValueSource source, bool keepEdits);
    int outputSettingsEditCount() const;

    // --- The sections with an edited copy beside the device's, one shape
    // each (SectionCopies); a change of one emits its signal below.
    // Encoder & system settings, key = a key of settingSpecs(). A device's
    // values are its whole section (mergeWhole).
    using SettingsCopies = SectionCopies<QString, QVariant>;
    SettingsCopies& settings() { return m_settings; }
    const SettingsCopies& settings() const { return m_settings; }

    // --- Users, in the same shape with the list the users page shows
    // (UserCopies); a change emits usersChanged.
    UserCopies& users() { return m_users; }
    const UserCopies& users() const { return m_users; }

    // --- PLC networks, key = plcKey(area, number)
    static int plcKey(int area, int number) { return plcNetworkKey(area, number); }
    using PlcCopies = SectionCopies<int, PlcNetwork>;
    PlcCopies& plc() { return m_plc; }
    const PlcCopies& plc() const { return m_plc; }
    static QMap<int, PlcNetwork> plcByKey(const QList<PlcNetwork>& networks);
    // As shown, or an empty network of that place.
    PlcNetwork plcNetwork(int area, int number) const;

    // --- Dead-time modes (table interface), key = output (1-based). Word 0
    // of a mode, the dead time of mode Normal, is the plain dead time the
    // Dead times page shows: its one home is the cam section. The copies
    // here hold the mode and the switch-on/-off times, and 0 for word 0;
    // the functions below read and take a whole OutputDeadTime.
    using DeadTimeModeCopies = SectionCopies<int, OutputDeadTime>;
    const DeadTimeModeCopies& deadTimeModes() const { return m_deadTimeModes; }
    // One output's mode as shown / as on the device (nullopt: not known).
    std::optional<OutputDeadTime> deadTimeMode(int output) const;
    std::optional<OutputDeadTime> deviceDeadTimeMode(int output) const;
    // Every output's, as shown (what a project saved now holds) / on the device.
    DeadTimeModes shownDeadTimeModes() const;
    DeadTimeModes deviceDeadTimeModes() const;
    // Whether the output's mode, or its times, differ from the device's.
    bool deadTimeModeChanged(int output) const;
    // The person wants `deadTime` on `output`: word 0 goes to the cam section.
    void editDeadTimeMode(int output, const OutputDeadTime& deadTime);
    // The device holds `deadTime` on `output` now (a write's read-back).
    void setDeviceDeadTimeMode(int output, const OutputDeadTime& deadTime);
    // Modes that arrive, by merge()'s rule; a device's are its whole
    // section. Only outputs the device has keep or take an edit once it was
    // read (the page has no row to show another in).
    void mergeDeadTimeModes(const DeadTimeModes& modes, ValueSource source, bool keepEdits);

    // --- The table interface's other sections; a change of any emits
    // tableSectionsChanged. Analogue cams, key = analogue output 1..14.
    using AnalogueCamCopies = SectionCopies<int, AnalogueCamTrack>;
    AnalogueCamCopies& analogueCams() { return m_analogueCams; }
    const AnalogueCamCopies& analogueCams() const { return m_analogueCams; }
    SingleCopy<ProgrammingProgram>& programmingProgram() { return m_programmingProgram; }
    const SingleCopy<ProgrammingProgram>& programmingProgram() const {
        return m_programmingProgram;
    }
    // true: locked.
    SingleCopy<bool>& eepromLock() { return m_eepromLock; }
    const SingleCopy<bool>& eepromLock() const { return m_eepromLock; }

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
    // (see CamSection::forgetDeviceCopies), and with them what was only
    // the old device's; of the edits, what `carry` says stays and counts as
    // not on the device, and a read of the new device keeps it over its
    // values without asking (takeIncoming). `note` says so until the next
    // read of everything.
    void forgetDeviceCopies(const QString& note, CarryOver carry);
    // A section the connected protocol lacks: its device copy is not this
    // device's state and is forgotten with its read time, edits stay.
    void forgetDeviceSection(ProjectPart part);
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
    void deadTimeModesChanged();
    void tableSectionsChanged();
    void readTimesChanged();
    void changedCountChanged(int count);
    void otherDeviceNoteChanged();

protected:
    // The cam section's holder: it is told of every change of the device
    // and of clear()/forgetDeviceCopies(), and calls notifyChanged() when
    // its changed count changes.
    void attachCams(CamSection* cams);
    void notifyChanged();

private:
    // Calls visit(section, the part its read time is kept under, its
    // signal) for each of the sections in the one shape (self: this
    // workspace, const or not).
    template <class Self, class Visit>
    static void forEachSection(Self& self, Visit visit);

    DeviceInfo m_info;
    QString m_projectPath;
    bool m_infoFromDevice = false;
    CamSection* m_camSection = nullptr;
    ProjectReadTimes m_readAt;
    SettingsCopies m_settings;
    UserCopies m_users;
    PlcCopies m_plc;
    DeadTimeModeCopies m_deadTimeModes;
    AnalogueCamCopies m_analogueCams;
    SingleCopy<ProgrammingProgram> m_programmingProgram;
    SingleCopy<bool> m_eepromLock;
    int m_lastCount = 0;
    std::optional<DeviceInfo> m_copiesFrom;
    bool m_fingerprintKnown = false;
    QString m_otherDeviceNote;
    std::optional<CarriedFrom> m_carriedFrom;
};

}  // namespace cambench
