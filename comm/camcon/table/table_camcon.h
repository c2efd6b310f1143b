#pragma once

#include "short_client.h"
#include "table_link.h"

#include "comm/camcon/camcon_device.h"

#include <memory>

namespace cambench::comm::table {

// A CamCon over its table interface (3964R/RK512, manual chapter 3): every
// operation reads or writes data words through a TableLink, driven by the
// table map. Output n is data area n, programs count from 0 as on the
// device. Cams are read and written in the "programming program" (area 201
// word 70), which each cam operation selects first, so that a program is
// edited while another one runs.
//
// Retry safety (3964R has no sequence numbers): every telegram this class
// sends is safe to repeat - reads, absolute writes, whole-track rewrites
// (cam 1 onwards replaces the track, later telegrams write absolute
// places), program change, error reset. Not used, because a repeat would
// act twice: writing area 1..200 word 254 (shifts every cam), deleting or
// creating a single cam by its place (the places behind it move), and the
// hardware reset (area 205 word 2, never acknowledged).
class TableCamCon : public CamConDevice {
public:
    // Owns its link over `transport`.
    TableCamCon(Transport& transport, const TableSettings& settings, const LineTiming& line);
    // Uses a link owned by the caller (tests, the benchmark).
    explicit TableCamCon(TableLink& link);
    ~TableCamCon() override;

    TableLink& link() { return m_link; }

    QString protocolId() const override;
    RequestEngine& engine() override { return m_link.engine(); }
    Result<QString> probe() override {
        m_link.setProbing();
        return CamConDevice::probe();
    }
    bool has(CamConCapability capability) const override;
    QString lacks(CamConCapability capability) const override;

    Result<DeviceInfo> readInfo() override;
    // Position and speed from area 201, program, device status and outputs
    // from the short status query 0x01, inputs from area 202.
    Result<DeviceStatus> readStatus(int outputs, int inputs) override;
    Status resetError() override;                // short command 0x02
    Status selectProgram(int program) override;  // short command 0x03

    Result<Track> readTrack(int program, int output) override;
    Result<CamProgram> readProgram(int program, int outputs,
                                   const ProgressFn& progress = {}) override;
    // One whole-track rewrite (manual 3.1).
    Status writeTrack(int program, const Track& track) override;
    Status deleteProgram(int program) override;
    Status copyProgram(int from, int to) override;
    Status copyTrack(int program, int fromOutput, int toOutput) override;

    // Word 0 of areas 1..200: the dead time of mode Normal.
    Result<DeadTimes> readDeadTimes(int outputs) override;
    Status writeDeadTime(int output, qint32 tenthsMs) override;
    Result<QString> readOutputName(int output) override;
    Status writeOutputName(int output, const QString& name) override;
    Result<QString> readProgramName(int program) override;
    Status writeProgramName(int program, const QString& name) override;

    Result<SystemSettings> readSettings(QStringList* skipped = nullptr) override;
    Status writeSettings(const SystemSettings& settings, const SystemSettings& onDevice) override;
    Result<QVariant> readSetting(const QString& key) override;

    Result<QList<User>> readUsers() override;
    Status writeUser(const QString& oldNumber, const User& user) override;
    Status deleteUser(const QString& number) override;

    Result<PlcNetwork> readPlcNetwork(int area, int number) override;
    Status writePlcNetwork(const PlcNetwork& network) override;
    Result<qint32> readPlcActual(int area, int number) override;
    Result<qint32> readPlcSetpoint(int area, int number) override;

    Result<EepromImage> backup(const ProgressFn& progress = {}) override;
    Status restore(const EepromImage& image, const ProgressFn& progress = {}) override;
    Result<QList<int>> scanBus(int first, int last, const ProgressFn& progress = {}) override;
    Result<QByteArray> raw(const QByteArray& request) override;

    Result<DeadTimeModes> readDeadTimeModes(int outputs) override;
    Status writeDeadTimeMode(int output, const OutputDeadTime& deadTime) override;
    Result<int> readAnalogueOutputCount() override;
    Result<AnalogueCamTrack> readAnalogueCams(int analogueOutput) override;
    Status writeAnalogueCams(const AnalogueCamTrack& track) override;
    Result<ProgrammingProgram> readProgrammingProgram() override;
    Status writeProgrammingProgram(const ProgrammingProgram& programming) override;
    Result<bool> readEepromLock() override;
    Status writeEepromLock(bool locked) override;
    ShortClient* shortCommands() override { return &m_short; }

private:
    // Area 201 word 70: the program areas 1..200 read and write.
    Status selectProgrammingProgram(int program);
    // The pairs (cams, analogue base points) of one area from word 1;
    // `countKey` names the word that counts them.
    Result<QList<qint32>> readPairWords(int area, QStringView countKey, const QString& what);
    Result<QList<Cam>> readTrackCams(int output);
    Status writePairWords(int area, const QList<qint32>& words, const QString& what, int pairs);
    // The area of output `output` (1..200), or a usage error.
    Result<int> trackArea(int output) const;
    // The highest cam (or base point) number the variant reaches.
    int reachablePairs() const;
    // The most cams (or base points) written to one area: without the count
    // word (e38) one reachable place stays empty, so that a read can tell
    // the end of the track from places it cannot reach.
    int writablePairs() const;

    std::unique_ptr<TableLink> m_ownLink;
    TableLink& m_link;
    ShortClient m_short{m_link};
};

}  // namespace cambench::comm::table
