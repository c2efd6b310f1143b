#include "sim_mc1_controller.h"

#include "comm/mc1/mc1_address.h"
#include "comm/mc1/mc1_catalogue.h"
#include "comm/mc1/mc1_parameters.h"

#include <algorithm>
#include <cmath>

namespace cambench::comm {

namespace {

constexpr int kMemorySize = kMc1MemorySize;
constexpr int kMaxBlock = kMc1MaxBlockRead;
constexpr int kMaxRead = kMc1MaxMemoryRead;
constexpr int kProgramLength = 0x400;

QByteArray ack() {
    return QByteArray(1, char(kMc1Ack));
}

QByteArray nak() {
    return QByteArray(1, char(kMc1Nak));
}

quint8 at(const QByteArray& data, int index) {
    return quint8(data.at(index));
}

qint64 wrapped(qint64 value, int bits) {
    const qint64 span = qint64(1) << bits;
    value &= span - 1;
    return value >= span / 2 ? value - span : value;
}

}  // namespace

SimMc1Controller::SimMc1Controller(Mc1Variant variant)
    : m_variant(variant), m_memory(kMemorySize, '\0') {}

void SimMc1Controller::setVariable(int number, qint64 value) {
    m_variables.insert(number, wrapped(value, mc1VariableBits(m_variant)));
}

quint8 SimMc1Controller::flagPage() const {
    return mc1ExternalFlagPage(isMc200(m_variant));
}

QByteArray& SimMc1Controller::page(quint8 number) {
    auto it = m_pages.find(number);
    if (it == m_pages.end()) it = m_pages.insert(number, QByteArray(256, '\0'));
    return *it;
}

quint8 SimMc1Controller::externalByte(quint8 number, quint8 address) const {
    return m_pages.contains(number) ? quint8(m_pages.value(number).at(address)) : 0;
}

void SimMc1Controller::setBit(const Mc1BitAddress& address, bool on) {
    const quint8 before =
        address.external ? externalByte(address.page, address.address) : m_ram[address.address];
    const quint8 after = on ? quint8(before | address.mask()) : quint8(before & ~address.mask());
    if (address.external)
        page(address.page)[address.address] = char(after);
    else
        m_ram[address.address] = after;
}

int SimMc1Controller::requestLength(const QByteArray& bytes) const {
    if (bytes.isEmpty()) return 0;
    if (mc1HasCommandByte(at(bytes, 0)) && bytes.size() < 3) return 0;
    const Mc1Telegram* t = mc1RequestRow(m_variant, bytes);
    if (!t) return -1;
    if (t->requestData >= 0) return 2 + (t->command >= 0 ? 1 : 0) + t->requestData;
    // WRMEM: address u16, n, then n bytes.
    return bytes.size() < 5 ? 0 : 5 + at(bytes, 4);
}

void SimMc1Controller::setAxes(const QList<int>& logical) {
    m_presentAxes = logical;
    std::sort(m_presentAxes.begin(), m_presentAxes.end());
}

QByteArray SimMc1Controller::handle(const QByteArray& request, qint64 nowMs) {
    m_received << request;  // (SimMc1Line::receive logs it for --verbose)
    if (request.size() < 2 || requestLength(request) != request.size() ||
        mc1Checksum(request) != at(request, 1))
        return nak();
    return answer(request, nowMs);
}

QByteArray SimMc1Controller::answer(const QByteArray& request, qint64 nowMs) {
    // handle() checked the length, so the row exists.
    const Mc1Telegram& t = *mc1RequestRow(m_variant, request);
    const QByteArray p = request.mid(t.command >= 0 ? 3 : 2);
    const auto u16 = [&p](int i) { return int(mc1FromLittleEndian(p.mid(i, 2), false)); };
    const auto reply = [&t](const QByteArray& data) { return mc1Telegram(t.answerOpcode, data); };
    switch (t.op) {
        case Mc1Op::ReadVariable:
            return reply(
                mc1LittleEndian(m_variables.value(u16(0)), mc1VariableBits(m_variant) / 8));
        case Mc1Op::WriteVariable:
            // 24 bits, sign-extended on an MC200 (provisional P3).
            setVariable(u16(0), mc1FromLittleEndian(p.mid(2, 3), true));
            return ack();
        case Mc1Op::WriteVariable32:
            setVariable(u16(0), mc1FromLittleEndian(p.mid(2, 4), true));
            return ack();
        case Mc1Op::ReadByteInternal:
            return reply(QByteArray(1, char(m_ram[at(p, 0)])));
        case Mc1Op::WriteByteInternal:
            m_ram[at(p, 0)] = at(p, 1);
            return ack();
        case Mc1Op::ReadByteExternal:
            return reply(QByteArray(1, char(externalByte(at(p, 1), at(p, 0)))));
        case Mc1Op::WriteByteExternal:
            page(at(p, 1))[at(p, 0)] = char(at(p, 2));
            return ack();
        case Mc1Op::WriteBitInternal:
        case Mc1Op::WriteBitExternal: {
            // 2^bit sets the bit, NOT 2^bit clears it; anything else is NAKed.
            const quint8 flag = at(p, 1);
            const int ones = __builtin_popcount(flag);
            if (ones != 1 && ones != 7) return nak();
            const quint8 address = at(p, 0);
            const bool internal = t.op == Mc1Op::WriteBitInternal;
            const quint8 before = internal ? m_ram[address] : externalByte(flagPage(), address);
            const quint8 after = ones == 1 ? quint8(before | flag) : quint8(before & flag);
            if (internal)
                m_ram[address] = after;
            else
                page(flagPage())[address] = char(after);
            return ack();
        }
        case Mc1Op::ReadBlock: {
            const int n = at(p, 3);
            if (n < 1 || n > kMaxBlock) return nak();
            QByteArray data;
            for (int i = 0; i < n; ++i) {
                const quint8 address = quint8(at(p, 0) + i);
                data.append(char(at(p, 2) ? externalByte(at(p, 1), address) : m_ram[address]));
            }
            return reply(data);
        }
        case Mc1Op::ReadMemory6:
            return reply(m_memory.mid(u16(0), 6).leftJustified(6, '\0'));
        case Mc1Op::ReadMemory: {
            const int n = at(p, 2);
            if (n < 1 || n > kMaxRead) return nak();
            return reply(m_memory.mid(u16(0), n).leftJustified(n, '\0'));
        }
        case Mc1Op::WriteMemory: {
            const int n = at(p, 2);
            const int address = u16(0);
            if (address + n > kMemorySize) return nak();
            m_memory.replace(address, n, p.mid(3, n));
            return ack();
        }
        case Mc1Op::ReadStatus: {
            const std::optional<qint32> value = statusParameter(u16(0), nowMs);
            if (!value) return nak();
            return reply(mc1LittleEndian(*value, 4));
        }
        case Mc1Op::WriteStatus:
            m_status.insert(u16(0), qint32(mc1FromLittleEndian(p.mid(2, 4), true)));
            return ack();
        case Mc1Op::ReadTable: {
            // The axes present fill the physical slots in order, servos
            // (type 1): provisional; an axis it lacks is refused.
            const int slot = int(m_presentAxes.indexOf(at(p, 2)));
            if (slot < 0) return nak();
            QByteArray data;
            data.append(char(slot));
            data.append(char(1));
            return reply(data);
        }
        case Mc1Op::ProgramStatus: {
            const quint8 flags = quint8((m_present ? 1 : 0) | (m_running ? 2 : 0));
            return reply(QByteArray(1, char(flags)) + mc1LittleEndian(programCounter(nowMs), 2));
        }
        case Mc1Op::ProgramStart:
            if (!m_present) return nak();
            if (!m_running) m_runStartMs = nowMs;
            m_running = true;
            return ack();
        case Mc1Op::ProgramStop:
            m_pc = programCounter(nowMs);
            m_running = false;
            return ack();
        case Mc1Op::ProgramStep:
            if (!m_present) return nak();
            m_pc = quint16((programCounter(nowMs) + 1) % kProgramLength);
            m_running = false;
            return ack();
        case Mc1Op::ProgramDelete:
            m_present = m_running = false;
            m_pc = 0;
            return ack();
        case Mc1Op::EndOfTransfer:
            m_present = true;
            m_running = false;
            m_pc = 0;
            return ack();
        case Mc1Op::UdbAddress:
            return reply(mc1LittleEndian(m_udbAddress, 4));
        case Mc1Op::Reset:
            m_running = false;
            m_pc = 0;
            if (at(p, 0) & 2) m_variables.clear();  // b1: total wipe
            return ack();
        case Mc1Op::PrepareTransfer:
        case Mc1Op::Display:
            return ack();
        case Mc1Op::Flash:
            if (at(p, 0) == 1) {
                m_flashedVariables = m_variables;
            } else if (at(p, 0) == 2) {
                m_variables = m_flashedVariables;
            } else {
                return nak();
            }
            return ack();
        case Mc1Op::AxisCommand:
            return axisCommand(at(p, 0), at(p, 1), 0, false, nowMs);
        case Mc1Op::AxisDataCommand:
            return axisCommand(at(p, 0), at(p, 1), qint32(mc1FromLittleEndian(p.mid(2, 4), true)),
                               true, nowMs);
    }
    return nak();
}

void SimMc1Controller::startMove(int axis, double target, qint64 nowMs) {
    Axis& a = m_axes[axis];
    a.from = axisPosition(axis + 1, nowMs);
    a.target = target;
    a.startMs = nowMs;
    a.continuous = false;
}

QByteArray SimMc1Controller::axisCommand(int logical, quint8 command, qint32 value, bool withValue,
                                         qint64 nowMs) {
    if (!m_presentAxes.contains(logical)) return nak();
    const int i = logical - 1;
    Axis& a = m_axes[i];
    const double here = axisPosition(logical, nowMs);
    if (!withValue) {
        switch (command) {
            case 0x06:  // home
                a.homed = true;
                startMove(i, 0, nowMs);
                return ack();
            case 0x07:  // start to the preloaded value
                startMove(i, a.target, nowMs);
                return ack();
            case 0x08:  // stop (programmed ramp)
            case 0x09:  // stop (maximum ramp)
                a.from = a.target = here;
                a.continuous = false;
                a.startMs = nowMs;
                return ack();
            case 0x11:  // acknowledge axis error
                return ack();
        }
        return nak();
    }
    switch (command) {
        case 0x01:  // preload relative
            a.target = here + value;
            return ack();
        case 0x02:  // preload absolute
            a.target = value;
            return ack();
        case 0x03:  // start to absolute
        case 0x12:
            startMove(i, value, nowMs);
            return ack();
        case 0x04:  // start relative
        case 0x13:
            startMove(i, here + value, nowMs);
            return ack();
        case 0x05:  // continuous
            a.from = here;
            a.startMs = nowMs;
            a.continuous = true;
            a.direction = value ? 1 : -1;
            return ack();
        case 0x0C:  // speed
        case 0x0E:
            if (value <= 0) return nak();
            a.from = here;
            a.startMs = nowMs;
            a.speed = value;
            return ack();
        case 0x00:
        case 0x0A:
        case 0x0B:
        case 0x0D:
        case 0x10:
            return ack();
    }
    return nak();
}

quint16 SimMc1Controller::programCounter(qint64 nowMs) const {
    // A running program advances one instruction a millisecond through a
    // program of kProgramLength instructions.
    if (!m_running) return m_pc;
    return quint16((m_pc + (nowMs - m_runStartMs)) % kProgramLength);
}

std::optional<qint32> SimMc1Controller::statusParameter(int parameter, qint64 nowMs) const {
    // The axes' parameters, by its own table.
    for (int axis : m_presentAxes) {
        const Axis& a = m_axes.at(axis - 1);
        if (parameter == m_parameters.number(axis, Mc1AxisValue::Position))
            return axisPosition(axis, nowMs);
        if (parameter == m_parameters.number(axis, Mc1AxisValue::Target))
            return qint32(std::lround(a.target));
        if (parameter == m_parameters.number(axis, Mc1AxisValue::Status))
            return (axisMoving(axis, nowMs) ? kMc1AxisMoving : 0) | (a.homed ? kMc1AxisHomed : 0);
    }
    // Others as written before; one never written it does not know.
    if (!m_status.contains(parameter)) return std::nullopt;
    return m_status.value(parameter);
}

qint32 SimMc1Controller::axisPosition(int logical, qint64 nowMs) const {
    const Axis& a = m_axes.at(logical - 1);
    const double travelled = a.speed * double(nowMs - a.startMs) / 1000.0;
    if (a.continuous) return qint32(std::lround(a.from + a.direction * travelled));
    const double distance = a.target - a.from;
    if (std::abs(distance) <= travelled) return qint32(std::lround(a.target));
    return qint32(std::lround(a.from + (distance > 0 ? travelled : -travelled)));
}

SimShaftMotion SimMc1Controller::axisMotion(int logical, qint64 nowMs) const {
    const Axis& a = m_axes.at(logical - 1);
    const double here = axisPosition(logical, nowMs);
    if (a.continuous) return {here, a.direction * a.speed, std::nullopt};
    if (!axisMoving(logical, nowMs)) return {here, 0.0, std::nullopt};
    return {here, a.target >= here ? a.speed : -a.speed, a.target};
}

bool SimMc1Controller::axisMoving(int logical, qint64 nowMs) const {
    const Axis& a = m_axes.at(logical - 1);
    return a.continuous || axisPosition(logical, nowMs) != qint32(std::lround(a.target));
}

}  // namespace cambench::comm
