#pragma once

#include "ascii_link.h"

#include "comm/camcon/camcon_device.h"

#include <memory>

namespace cambench::comm {

// A CamCon over the ASCII protocol (Standard or Multiuser framing): each
// operation a sequence of catalogue commands over an AsciiLink. Converts
// the device's 0-based output numbers to the model's 1-based ones; nothing
// 0-based leaves this folder.
class AsciiCamCon : public CamConDevice {
public:
    // Owns its link over `transport`.
    AsciiCamCon(Transport& transport, const AsciiSettings& settings, const LineTiming& line);
    // Uses a link owned by the caller (tests, the benchmark).
    explicit AsciiCamCon(AsciiLink& link);
    // Owns `link` (another transport framing, Cam-BUS).
    explicit AsciiCamCon(std::unique_ptr<AsciiLink> link);
    ~AsciiCamCon() override;

    AsciiLink& link() { return m_link; }

    QString protocolId() const override;
    RequestEngine& engine() override { return m_link.engine(); }
    void setDevice(int device) override { m_link.setDevice(device); }
    bool has(CamConCapability capability) const override;

    Result<DeviceInfo> readInfo() override;
    Result<DeviceStatus> readStatus(int outputs, int inputs) override;
    Status resetError() override;
    Status selectProgram(int program) override;

    // Cam tracks: ?NF then ?NN until no more cams.
    Result<Track> readTrack(int program, int output) override;
    Result<CamProgram> readProgram(int program, int outputs,
                                   const ProgressFn& progress = {}) override;
    // Sends only the cams that differ, ordered so that a refused step
    // leaves the track as it was where the protocol allows: cams that
    // overlap nothing on the track go in before any is deleted, the others
    // after the deletes; when a step is refused, what was done is undone
    // (inserted cams deleted, deleted ones inserted again). The error says
    // whether the track could be put back.
    Status writeTrack(int program, const Track& track) override;
    Status writeTrackFrom(int program, const Track& track, const Track& onDevice) override;
    Status deleteProgram(int program) override;
    Status copyProgram(int from, int to) override;
    Status copyTrack(int program, int fromOutput, int toOutput) override;

    Result<DeadTimes> readDeadTimes(int outputs) override;
    Status writeDeadTime(int output, qint32 tenthsMs) override;
    Result<QString> readOutputName(int output) override;
    Status writeOutputName(int output, const QString& name) override;
    Result<QString> readProgramName(int program) override;
    Status writeProgramName(int program, const QString& name) override;

    Result<SystemSettings> readSettings(QStringList* skipped = nullptr) override;
    Status writeSettings(const SystemSettings& settings, const SystemSettings& onDevice) override;
    // Reads the device's settings first, then writes what differs.
    Status writeSettings(const SystemSettings& settings);
    Result<QVariant> readSetting(const QString& key) override;

    Result<QList<User>> readUsers() override;
    // `oldNumber` empty for a new user.
    Status writeUser(const QString& oldNumber, const User& user) override;
    Status deleteUser(const QString& number) override;

    Result<PlcNetwork> readPlcNetwork(int area, int number) override;
    Status writePlcNetwork(const PlcNetwork& network) override;
    Result<qint32> readPlcActual(int area, int number) override;
    Result<qint32> readPlcSetpoint(int area, int number) override;

    // Whole EEPROM (notes 6).
    Result<EepromImage> backup(const ProgressFn& progress = {}) override;
    Status restore(const EepromImage& image, const ProgressFn& progress = {}) override;

    // Multiuser: device numbers in [first,last] that answer ?UNIT.
    Result<QList<int>> scanBus(int first, int last, const ProgressFn& progress = {}) override;
    // With an explicit per-number timeout (0 = derived from the line).
    Result<QList<int>> scanBus(int first, int last, int timeoutMs, const ProgressFn& progress = {});
    // "?IFGWG" or "!PAU0003": lead, command letters and data; the checksum
    // is added. The reply's body, user numbers masked.
    Result<QByteArray> raw(const QByteArray& request) override;

private:
    std::unique_ptr<AsciiLink> m_ownLink;
    AsciiLink& m_link;
};

}  // namespace cambench::comm
