#pragma once

#include "ascii_link.h"

#include "model/camcon/cam_program.h"
#include "model/camcon/dead_times.h"
#include "model/camcon/device_info.h"
#include "model/camcon/eeprom_image.h"
#include "model/camcon/plc_network.h"
#include "model/result.h"
#include "model/camcon/system_settings.h"
#include "model/camcon/user.h"

#include <functional>

namespace cambench::comm {

using ProgressFn = std::function<void(qint64 done, qint64 total)>;

// What a user asks of one device ("read program 3"), as sequences of
// catalogue commands over a ProtocolLink. Synchronous: runs on the worker
// thread inside a job. Converts the device's 0-based output numbers to the
// 1-based numbers of the model; nothing 0-based leaves this class.
class CamConClient {
public:
    explicit CamConClient(ProtocolLink& link) : m_link(link) {}

    Result<DeviceInfo> readInfo();
    Result<DeviceStatus> readStatus(int outputs, int inputs);
    Status resetError();
    Status selectProgram(int program);

    // Cam tracks: ?NF then ?NN until no more cams.
    Result<Track> readTrack(int program, int output);
    Result<CamProgram> readProgram(int program, int outputs, const ProgressFn& progress = {});
    // Makes the device's track equal `track` (deletes, inserts; unchanged
    // cams are left alone).
    Status writeTrack(int program, const Track& track);
    Status deleteProgram(int program);
    Status copyProgram(int from, int to);
    Status copyTrack(int program, int fromOutput, int toOutput);

    Result<DeadTimes> readDeadTimes(int outputs);
    Status writeDeadTime(int output, qint32 tenthsMs);
    Result<QString> readOutputName(int output);
    Status writeOutputName(int output, const QString& name);
    Result<QString> readProgramName(int program);
    Status writeProgramName(int program, const QString& name);

    // Settings the device answers :Z to are left out and, when `skipped` is
    // given, listed there ("GSPLL (specialEncoder.pll.*)").
    Result<SystemSettings> readSettings(QStringList* skipped = nullptr);
    // Writes the keys of `settings` whose values differ from the device's
    // (read first); read-only keys are ignored. Keys absent stay as they are.
    Status writeSettings(const SystemSettings& settings);
    // One setting by its model key (reads the command that holds it).
    Result<QVariant> readSetting(const QString& key);

    Result<QList<User>> readUsers();
    // `oldNumber` empty for a new user.
    Status writeUser(const QString& oldNumber, const User& user);
    Status deleteUser(const QString& number);

    Result<PlcNetwork> readPlcNetwork(int area, int number);
    Status writePlcNetwork(const PlcNetwork& network);
    Result<qint32> readPlcActual(int area, int number);
    Result<qint32> readPlcSetpoint(int area, int number);

    // Whole EEPROM (notes 6).
    Result<EepromImage> backup(const ProgressFn& progress = {});
    // Erases the device and writes `image`; the caller has validated it.
    // On failure the message says whether the device is erased or partial.
    Status restore(const EepromImage& image, const ProgressFn& progress = {});

    // Multiuser: device numbers in [first,last] that answer ?UNIT, with a
    // short per-number timeout.
    Result<QList<int>> scanBus(int first = 0, int last = 63, int timeoutMs = 60,
                               const ProgressFn& progress = {});

private:
    ProtocolLink& m_link;
};

}  // namespace cambench::comm
