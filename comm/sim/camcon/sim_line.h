#pragma once

#include "comm/sim/sim_faults.h"
#include "comm/sim/sim_injections.h"
#include "comm/sim/sim_output.h"
#include "sim_camcon_endpoint.h"
#include "sim_device.h"

#include "comm/camcon/ascii/stream_decoder.h"

#include <QByteArrayView>
#include <QHash>
#include <QList>

#include <memory>
#include <optional>
#include <vector>

namespace cambench::comm {

// The bus between the PC and one or more simulated devices. Decodes what
// the PC sends and returns what the devices answer, as wire bytes, after
// fault injection. Standard framing: the (single) device answers. Multiuser:
// only the addressed device answers, and a repeated block number from the
// same PC makes it repeat its last answer without executing again. A frame
// with a bad checksum gets no answer, as on a real line.
class SimLine : public SimCamConEndpoint {
public:
    struct Counters {
        int frames = 0;        // requests decoded with a good checksum
        int badChecksums = 0;  // ignored
        int unaddressed = 0;   // Multiuser frames for a device not on the line or from another PC
        int repeats = 0;       // answers repeated for a reused block number
    };

    explicit SimLine(Framing framing);

    Framing framing() const { return m_framing; }

    // Multiuser device numbers 0..63; the line owns the device.
    SimDevice& addDevice(std::unique_ptr<SimDevice> device);
    SimDevice* device(int number) const override;
    const std::vector<std::unique_ptr<SimDevice>>& devices() const { return m_devices; }

    void setFaults(const SimFaultSettings& settings) { m_faults = SimFaults(settings); }
    // Multiuser: answer only requests from this PC number (another master
    // on the bus is none of ours); unset = any.
    void setPcNumber(std::optional<int> number) { m_pcNumber = number; }
    const SimFaults& faults() const { return m_faults; }
    // Command log, dead devices and refusals on purpose (tests).
    SimInjections& injections() { return m_injections; }
    const Counters& counters() const { return m_counters; }

    QList<SimOutput> feed(QByteArrayView bytesFromPc);

    QList<SimOutput> receive(QByteArrayView bytes, qint64) override { return feed(bytes); }
    QString protocolName() const override;

private:
    struct LastAnswer {
        int block = -1;
        std::optional<SimOutput> output;  // as the device sent it, before faults
    };

    std::optional<SimOutput> answer(const Frame& request);
    std::optional<SimOutput> execute(SimDevice& device, const Frame& request);
    void updateChecksumMode();

    Framing m_framing;
    StreamDecoder m_decoder;
    std::vector<std::unique_ptr<SimDevice>> m_devices;
    QHash<int, QHash<int, LastAnswer>> m_lastAnswers;  // device -> PC number -> answer
    SimFaults m_faults;
    SimInjections m_injections;
    std::optional<int> m_pcNumber;
    Counters m_counters;
};

}  // namespace cambench::comm
