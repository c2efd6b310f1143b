#pragma once

#include "comm/device/device_connection.h"
#include "comm/device/progress.h"

#include "model/camcon/analogue_cams.h"
#include "model/camcon/cam_program.h"
#include "model/camcon/camcon_family_id.h"
#include "model/camcon/dead_time_modes.h"
#include "model/camcon/dead_times.h"
#include "model/camcon/device_info.h"
#include "model/camcon/eeprom_image.h"
#include "model/camcon/plc_network.h"
#include "model/camcon/programming_program.h"
#include "model/camcon/system_settings.h"
#include "model/camcon/user.h"
#include "model/result.h"

#include <QStringList>

namespace cambench::comm {

namespace table {
class ShortClient;
}

// What a CamCon protocol may or may not offer. The GUI and the CLI ask
// before they offer an action; a missing one comes with a reason.
enum class CamConCapability {
    Users,               // users and rights: ASCII only
    EepromBackup,        // whole-EEPROM backup and restore (?EE/!EE): ASCII only
    BusScan,             // device numbers on a bus: Multiuser, Cam-BUS
    Terminal,            // free-form requests typed by the user: ASCII
    OutputNames,         // output and program names: ASCII
    PlcNetworks,         // PLC links (?GMXSPS / data area 216)
    DeadTimeModes,       // dead-time modes and separate on/off dead times: table interface
    AnalogueCams,        // analogue cams (data areas 241..254): table interface
    EepromLock,          // EEPROM write lock, changes held in RAM: table interface
    ProgrammingProgram,  // a program other than the active one edited (DW70..73): table interface
    ShortCommands,       // the S7-CP340 coupling's short commands 0x01..0x07: table interface
};

// One user a bus scan found. Multiuser knows only CamCons (they answer);
// a token bus (Cam-BUS) also knows displays and PCs, which get the token
// but answer no CamCon command.
struct BusUser {
    enum Kind { CamCon, Other, ThisPc };
    int number = 0;
    Kind kind = CamCon;
    bool silent = false;  // in the bus's table but answering nothing
};
struct BusUsers {
    QList<BusUser> users;     // ascending
    bool kindsKnown = false;  // the protocol tells CamCons from other users
};

// Everything the GUI and the CLI ask of a CamCon, whatever the protocol.
// Runs on the worker thread inside a job; synchronous. Outputs and inputs
// count from 1, programs from 0: the protocols' own numbering stays in
// their folders.
class CamConDevice : public DeviceConnection {
public:
    QString familyId() const override { return camconFamilyId; }

    virtual bool has(CamConCapability capability) const = 0;
    // Why `capability` is missing, as a sentence naming the protocol that
    // has it: "Users exist only in the ASCII protocol (standard or multiuser)."
    virtual QString lacks(CamConCapability capability) const;
    // A Usage error carrying lacks(), for callers that must refuse.
    Error missing(CamConCapability capability) const;

    virtual Result<DeviceInfo> readInfo() = 0;
    // The identity readInfo() gives, in one line.
    Result<QString> identify() override;
    // camConIdentity() of readInfo().
    Result<DeviceIdentity> readIdentity() override;
    virtual Result<DeviceStatus> readStatus(int outputs, int inputs) = 0;
    virtual Status resetError() = 0;
    virtual Status selectProgram(int program) = 0;

    virtual Result<Track> readTrack(int program, int output) = 0;
    virtual Result<CamProgram> readProgram(int program, int outputs,
                                           const ProgressFn& progress = {}) = 0;
    // Makes the device's track equal `track`.
    virtual Status writeTrack(int program, const Track& track) = 0;
    // The same when the caller has just read the track (`onDevice`), so
    // that it is not read twice. By default it is read again.
    virtual Status writeTrackFrom(int program, const Track& track, const Track& onDevice) {
        Q_UNUSED(onDevice);
        return writeTrack(program, track);
    }
    virtual Status deleteProgram(int program) = 0;
    virtual Status copyProgram(int from, int to) = 0;
    virtual Status copyTrack(int program, int fromOutput, int toOutput) = 0;

    virtual Result<DeadTimes> readDeadTimes(int outputs) = 0;
    virtual Status writeDeadTime(int output, qint32 tenthsMs) = 0;
    virtual Result<QString> readOutputName(int output) = 0;
    virtual Status writeOutputName(int output, const QString& name) = 0;
    virtual Result<QString> readProgramName(int program) = 0;
    virtual Status writeProgramName(int program, const QString& name) = 0;

    // Settings the device does not know are left out and, when `skipped`
    // is given, listed there.
    virtual Result<SystemSettings> readSettings(QStringList* skipped = nullptr) = 0;
    // Writes the keys of `settings` whose values differ from `onDevice`
    // (read by the caller, so nothing is read twice); read-only keys are
    // ignored, keys absent stay as they are.
    virtual Status writeSettings(const SystemSettings& settings,
                                 const SystemSettings& onDevice) = 0;
    virtual Result<QVariant> readSetting(const QString& key) = 0;

    virtual Result<QList<User>> readUsers() = 0;
    virtual Status writeUser(const QString& oldNumber, const User& user) = 0;
    virtual Status deleteUser(const QString& number) = 0;

    virtual Result<PlcNetwork> readPlcNetwork(int area, int number) = 0;
    virtual Status writePlcNetwork(const PlcNetwork& network) = 0;
    virtual Result<qint32> readPlcActual(int area, int number) = 0;
    virtual Result<qint32> readPlcSetpoint(int area, int number) = 0;

    virtual Result<EepromImage> backup(const ProgressFn& progress = {}) = 0;
    // Erases the device and writes `image`; the caller has validated it.
    // On failure the message says whether the device is erased or partial.
    virtual Status restore(const EepromImage& image, const ProgressFn& progress = {}) = 0;

    // scanBus() (DeviceConnection): Multiuser and Cam-BUS; the others refuse it.
    // BusScan: the users on the bus; by default the CamCons scanBus() finds.
    virtual Result<BusUsers> scanUsers(const ProgressFn& progress = {});
    // A request typed by the user; returns the reply as text.
    virtual Result<QByteArray> raw(const QByteArray& request) = 0;

    // What only some protocols offer. Each default refuses with missing()
    // of its capability, so a protocol implements only what it has.

    // DeadTimeModes: mode and values of outputs 1..outputs.
    virtual Result<DeadTimeModes> readDeadTimeModes(int outputs);
    virtual Status writeDeadTimeMode(int output, const OutputDeadTime& deadTime);
    // AnalogueCams: how many analogue outputs the device says it has
    // (0..14): only outputs 1..count exist; a device without any refuses
    // their areas. Read before the analogue cams, never assumed to be 14.
    virtual Result<int> readAnalogueOutputCount();
    // AnalogueCams: the base points of analogue output 1..14.
    virtual Result<AnalogueCamTrack> readAnalogueCams(int analogueOutput);
    // Makes the device's base points of `track.output` equal `track.points`.
    virtual Status writeAnalogueCams(const AnalogueCamTrack& track);
    // ProgrammingProgram.
    virtual Result<ProgrammingProgram> readProgrammingProgram();
    virtual Status writeProgrammingProgram(const ProgrammingProgram& programming);
    // EepromLock: true = locked, later changes are kept in RAM only and are
    // lost when the device is switched off.
    virtual Result<bool> readEepromLock();
    virtual Status writeEepromLock(bool locked);
    // The S7-CP340 short commands 0x01..0x07, as a PLC sends them: on the
    // table interface only, nullptr on the others.
    virtual table::ShortClient* shortCommands() { return nullptr; }
};

}  // namespace cambench::comm
