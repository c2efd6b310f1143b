#pragma once

#include "comm/mc1/mc1_address.h"
#include "comm/mc1/mc1_parameters.h"
#include "comm/mc1/mc1_variant.h"
#include "comm/sim/sim_shaft.h"

#include <QByteArray>
#include <QList>
#include <QMap>

#include <array>
#include <optional>

namespace cambench::comm {

// A simulated MC100 or MC200 of one variant: what a complete request
// telegram does to it and the answer it gives (an empty answer: none).
// Variables, internal RAM, external RAM pages, memory, status parameters,
// the PLC program's state and up to eight axes that move with time. Like
// the real one it checks neither variable numbers nor write addresses, and
// it NAKs an opcode its variant lacks, a bad checksum or a bad length, an
// axis command or RDTABLE for an axis it lacks and RDSTAT of a parameter it
// does not know.
class SimMc1Controller {
public:
    explicit SimMc1Controller(Mc1Variant variant);

    Mc1Variant variant() const { return m_variant; }
    // `request` is one whole telegram; `nowMs` a monotonic clock (axes).
    QByteArray handle(const QByteArray& request, qint64 nowMs);
    // The length of the telegram that starts `bytes` once enough of it is
    // there to tell (WRMEM carries its n); 0 while unknown; -1 for a first
    // byte that starts no telegram of this variant.
    int requestLength(const QByteArray& bytes) const;

    // The logical axes it has (1..8 by default), each on the next physical
    // slot; commands for others are refused (NAK).
    void setAxes(const QList<int>& logical);
    const QList<int>& axes() const { return m_presentAxes; }
    // Where its PLC program's data block starts (SYSDATA 08).
    void setUdbAddress(quint32 address) { m_udbAddress = address; }
    // Its own axis parameter numbers (by default CamBench's guess).
    void setAxisParameters(const Mc1AxisParameterTable& table) { m_parameters = table; }
    // Every whole telegram it received, in order (tests count them).
    const QList<QByteArray>& received() const { return m_received; }

    // State, for tests and the demo.
    qint64 variable(int number) const { return m_variables.value(number); }
    void setVariable(int number, qint64 value);
    quint8 internalByte(quint8 address) const { return m_ram[address]; }
    quint8 externalByte(quint8 page, quint8 address) const;
    void setBit(const Mc1BitAddress& address, bool on);
    bool running() const { return m_running; }
    quint16 programCounter(qint64 nowMs) const;
    qint32 axisPosition(int axis, qint64 nowMs) const;
    bool axisMoving(int axis, qint64 nowMs) const;
    // How logical axis `axis` moves at `nowMs` (a simulated machine's shaft
    // follows it between telegrams).
    SimShaftMotion axisMotion(int axis, qint64 nowMs) const;

private:
    struct Axis {
        double from = 0;
        double target = 0;
        qint64 startMs = 0;
        double speed = 1000;  // units per second
        bool homed = false;
        bool continuous = false;
        int direction = 1;
    };
    QByteArray answer(const QByteArray& request, qint64 nowMs);
    QByteArray axisCommand(int axis, quint8 command, qint32 value, bool withValue, qint64 nowMs);
    void startMove(int axis, double target, qint64 nowMs);
    QByteArray& page(quint8 page);
    // RDSTAT: the axes' parameters from their motion, others as written.
    std::optional<qint32> statusParameter(int parameter, qint64 nowMs) const;
    quint8 flagPage() const;

    Mc1Variant m_variant;
    QMap<int, qint64> m_variables;
    std::array<quint8, 256> m_ram{};
    QMap<quint8, QByteArray> m_pages;
    QByteArray m_memory;
    QMap<int, qint32> m_status;
    bool m_present = true;
    bool m_running = false;
    quint16 m_pc = 0;  // while running: where it was at m_runStartMs
    qint64 m_runStartMs = 0;
    QMap<int, qint64> m_flashedVariables;
    std::array<Axis, 8> m_axes{};
    QList<int> m_presentAxes{1, 2, 3, 4, 5, 6, 7, 8};
    quint32 m_udbAddress = 0x00010000;
    Mc1AxisParameterTable m_parameters = mc1ProvisionalAxisParameters();
    QList<QByteArray> m_received;
};

}  // namespace cambench::comm
