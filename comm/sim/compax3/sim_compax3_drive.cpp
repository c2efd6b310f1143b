#include "sim_compax3_drive.h"

#include "comm/compax3/compax3_objects.h"
#include "comm/compax3/compax3_syntax.h"

#include <cmath>

namespace cambench::comm {

namespace {

constexpr double kJogVelocity = 50.0;  // units per second
constexpr double kEndLimit = 1000000.0;

QByteArray refused(int code) {
    return QStringLiteral("!%1").arg(code, 4, 16, QLatin1Char('0')).toUpper().toLatin1();
}

bool isComputed(const Compax3ObjectId& id) {
    return id == kCompax3LastError || id == kCompax3Position || id == kCompax3StatusWord ||
           id == kCompax3LastSet || id == kCompax3ControlWord || id == kCompax3Serial;
}

}  // namespace

SimCompax3Drive::SimCompax3Drive(QString type, QString serial)
    : m_type(std::move(type)), m_serial(std::move(serial)) {
    for (const Compax3ObjectInfo& info : Compax3Dictionary::builtin().objects()) {
        if (!info.parameter()) continue;
        const int set = info.id.subindex;
        switch (info.id.index) {
            case 1901:
                m_values.insert(info.id, compax3NumberText(set * 100.0));
                break;
            case 1902:
                m_values.insert(info.id, QStringLiteral("200"));
                break;
            case 1905:
                m_values.insert(info.id, QStringLiteral("1"));
                break;
            case 1906:
            case 1907:
                m_values.insert(info.id, QStringLiteral("1000"));
                break;
            default:
                m_values.insert(info.id, QStringLiteral("10000"));
                break;
        }
    }
}

QString SimCompax3Drive::infoString() const {
    // Fixed length, as the manual says of info strings.
    return QStringLiteral("Compax3 %1 F10 I10 T40 V04.02").arg(m_type);
}

double SimCompax3Drive::setValue(int object, int set) const {
    return compax3Number(m_values.value(Compax3ObjectId{object, set})).value_or(0.0);
}

void SimCompax3Drive::advance(qint64 nowMs) {
    const double seconds = m_lastMs < 0 ? 0.0 : double(nowMs - m_lastMs) / 1000.0;
    m_lastMs = nowMs;
    if (m_jog != 0) {
        m_position += m_jog * kJogVelocity * seconds;
        if (std::abs(m_position) > kEndLimit) {
            m_position = std::copysign(kEndLimit, m_position);
            raiseError(m_position > 0 ? 0x7323 : 0x7324);
        }
        return;
    }
    if (!m_moving) return;
    const double step = m_velocity * seconds;
    if (std::abs(m_target - m_position) <= step) {
        m_position = m_target;
        m_moving = false;
        m_lastSet = m_movingSet;
        if (m_movingSet == 0) m_zeroKnown = true;
    } else {
        m_position += m_target > m_position ? step : -step;
    }
}

SimShaftMotion SimCompax3Drive::motion() const {
    if (m_jog != 0)
        return {m_position, m_jog * kJogVelocity, std::copysign(kEndLimit, double(m_jog))};
    if (m_moving) return {m_position, m_target >= m_position ? m_velocity : -m_velocity, m_target};
    return {m_position, 0.0, std::nullopt};
}

void SimCompax3Drive::raiseError(int code) {
    m_error = code;
    m_powered = false;
    m_moving = false;
    m_jog = 0;
}

quint16 SimCompax3Drive::statusWord() const {
    quint16 word = 0x05;  // inputs I0 and I2
    if (m_error == 1) word |= 0x0100;
    if (m_powered && !moving()) word |= 0x0200;  // position reached
    if (!m_powered) word |= 0x0400;
    if (m_powered && !moving()) word |= 0x0800;
    if (m_zeroKnown) word |= 0x1000;
    return word;
}

QByteArray SimCompax3Drive::answer(const QByteArray& command, qint64 nowMs) {
    advance(nowMs);
    m_requests << compax3Canonical(command);
    const std::optional<Compax3Request> request = parseCompax3Request(m_requests.last());
    if (!request) return refused(1);
    if (request->kind == Compax3Request::Info) return infoString().toLatin1();
    if (m_missing.contains(request->id)) return refused(2);
    if (request->kind == Compax3Request::Read && m_unreadable.contains(request->id))
        return refused(5);
    if (request->kind == Compax3Request::Read) return read(request->id, request->hexAnswer);
    return write(request->id, request->value);
}

QByteArray SimCompax3Drive::read(const Compax3ObjectId& id, bool hex) const {
    QString value;
    if (id == kCompax3Serial)
        value = QLatin1Char('"') + m_serial + QLatin1Char('"');
    else if (id == kCompax3LastError)
        value = QString::number(m_error);
    else if (id == kCompax3Position)
        value = compax3NumberText(std::round(m_position * 1000) / 1000);
    else if (id == kCompax3StatusWord)
        value = QString::number(statusWord());
    else if (id == kCompax3LastSet)
        value = QString::number(m_lastSet);
    else if (id == kCompax3ControlWord)
        value = QString::number(m_control);
    else if (m_values.contains(id))
        value = m_values.value(id);
    else if (const Compax3ObjectInfo* info = Compax3Dictionary::builtin().find(id);
             info && !info->readable())
        return refused(3);
    else
        return refused(2);
    if (value.startsWith(QLatin1Char('"'))) {
        if (hex) return refused(6);
        return value.mid(1, value.size() - 2).toLatin1();
    }
    if (!hex) return value.toLatin1();
    const std::optional<double> number = compax3Number(value);
    if (!number || std::floor(*number) != *number) return refused(6);  // REAL in hex: refused
    return compax3HexText(qint64(*number)).toLatin1();
}

QByteArray SimCompax3Drive::write(const Compax3ObjectId& id, const QString& value) {
    const Compax3ObjectInfo* info = Compax3Dictionary::builtin().find(id);
    if (!info) return refused(2);
    if (!info->writable() || (isComputed(id) && id != kCompax3ControlWord)) return refused(3);
    if (value.contains(QLatin1Char(';'))) return refused(6);  // every object here is one value
    if (info->type == Compax3Type::Text) {
        if (!value.startsWith(QLatin1Char('"'))) return refused(6);
        m_values.insert(id, value);
        return ">";
    }
    if (value.startsWith(QLatin1Char('"'))) return refused(6);
    const std::optional<double> number = compax3Number(value);
    if (!number) return refused(1);  // "12,5" is a syntax error on the drive
    if (info->type == Compax3Type::Integer && std::floor(*number) != *number) return refused(6);
    if (!info->range.contains(*number)) return refused(4);
    if (id == kCompax3ControlWord) return control(quint16(*number));
    if (id.index == compax3StoreSet(0).index)  // 1904.n: stores set n
        return *number == kCompax3StoreSetsValue ? ">" : refused(4);
    m_values.insert(id, compax3NumberText(*number));
    return ">";
}

QByteArray SimCompax3Drive::control(quint16 word) {
    const quint16 before = m_control;
    const bool enable = word & compax3control::kEnable;
    const bool enableEdge = enable && !(before & compax3control::kEnable);
    const bool run = (word & compax3control::kRun) == compax3control::kRun;
    const bool startEdge = (word & compax3control::kStart) && !(before & compax3control::kStart);
    // The start needs power: the edge of b0 in the same word gives it.
    const bool poweredThen = enableEdge || (enable && m_powered);
    if (startEdge && (!run || !poweredThen || (m_error != 1 && !enableEdge))) return refused(5);
    m_control = word;
    if (enableEdge) {  // the rising edge: acknowledge, then power
        m_error = 1;
        m_powered = true;
    }
    if (!enable) m_powered = false;
    if (!m_powered || !run) {  // powerless, or the stop bits cleared: the axis stops
        m_moving = false;
        m_jog = 0;
        return ">";
    }
    m_jog = (word & compax3control::kJogPlus) ? 1 : (word & compax3control::kJogMinus) ? -1 : 0;
    if (m_jog != 0) m_moving = false;
    if (startEdge) {
        const int set = (word >> compax3control::kSetShift) & 0x1F;
        m_movingSet = set;
        m_velocity = std::max(1.0, setValue(1902, set));
        if (set == 0) {
            m_target = 0.0;  // homing
        } else {
            const double target = setValue(1901, set);
            m_target = setValue(1905, set) == 2 ? m_position + target : target;
        }
        m_moving = true;
    }
    return ">";
}

}  // namespace cambench::comm
