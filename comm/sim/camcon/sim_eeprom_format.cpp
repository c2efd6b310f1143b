#include "sim_eeprom_format.h"

#include "comm/sim/sim_log.h"

#include "comm/camcon/ascii/catalogue.h"
#include "comm/camcon/ascii/command_codec.h"

#include <QDataStream>
#include <QIODevice>

namespace cambench::comm::sim_eeprom {

namespace {

constexpr char kMagic[] = "CSIM";
constexpr quint8 kLayoutVersion = 1;
constexpr int kTextBytes = 22;
constexpr int kUserNumberBytes = 6;
constexpr int kCamsPerRecord = 10;

enum RecordType : quint8 {
    Cams = 1,
    DeadTime = 2,
    OutputName = 3,
    ProgramName = 4,
    User = 5,
    PlcNetwork = 6,
    Setting = 7,
    TextLine = 8,
};
constexpr char kUserText = 'B';
constexpr char kPlcText = 'E';

QByteArray fixedText(const QByteArray& text, int width) {
    QByteArray out = text.left(width - 1);
    out.resize(width, '\0');
    return out;
}

QByteArray untilNul(const QByteArray& raw) {
    const qsizetype nul = raw.indexOf('\0');
    return nul < 0 ? raw : raw.left(nul);
}

class Writer {
public:
    Writer() : m_stream(&m_bytes, QIODevice::WriteOnly) {}
    Writer& u8(int v) {
        m_stream << quint8(v);
        return *this;
    }
    Writer& u16(int v) {
        m_stream << quint16(v);
        return *this;
    }
    Writer& i32(qint32 v) {
        m_stream << v;
        return *this;
    }
    Writer& u32(quint32 v) {
        m_stream << v;
        return *this;
    }
    Writer& raw(const QByteArray& bytes) {
        m_stream.writeRawData(bytes.constData(), int(bytes.size()));
        return *this;
    }
    const QByteArray& bytes() const { return m_bytes; }

private:
    QByteArray m_bytes;
    QDataStream m_stream;
};

class Reader {
public:
    explicit Reader(const QByteArray& bytes) : m_bytes(bytes), m_stream(m_bytes) {}
    int u8() {
        quint8 v = 0;
        m_stream >> v;
        return v;
    }
    int u16() {
        quint16 v = 0;
        m_stream >> v;
        return v;
    }
    qint32 i32() {
        qint32 v = 0;
        m_stream >> v;
        return v;
    }
    quint32 u32() {
        quint32 v = 0;
        m_stream >> v;
        return v;
    }
    QByteArray raw(int count) {
        QByteArray out(count, '\0');
        if (m_stream.readRawData(out.data(), count) != count)
            m_stream.setStatus(QDataStream::ReadPastEnd);
        return out;
    }
    bool ok() const { return m_stream.status() == QDataStream::Ok; }

private:
    QByteArray m_bytes;
    QDataStream m_stream;
};

// Appends one record as a block; a record that cannot fit one block is a
// bug in this layout, logged rather than written half.
void appendRecord(QList<QByteArray>& blocks, RecordType type, const QByteArray& payload) {
    const int length = 1 + int(payload.size());
    const int sixes = (length + 5) / 6;
    if (sixes > 15) {
        qCWarning(commSimLog) << "EEPROM record of type" << type << "too long:" << length;
        return;
    }
    QByteArray block(1, char((sixes << 4) | type));
    block += payload;
    block.resize(sixes * 6, '\0');
    blocks.append(block);
}

QByteArray basicBlock(const SimState& state, const SimProfile& profile) {
    Writer w;
    w.raw(QByteArray(kMagic, 4)).u8(kLayoutVersion).raw(fixedText(profile.epromDate, 11));
    w.u16(profile.outputs).u16(profile.inputs).u16(profile.programs);
    w.i32(profile.minPosition).i32(profile.maxPosition).i32(profile.maxDeadTime);
    w.u16(state.activeProgram).i32(state.cams.camCount());
    QByteArray block = w.bytes();
    block.resize(kBasicBlockBytes, '\0');
    return block;
}

void appendCams(QList<QByteArray>& blocks, const SimCamStore& cams) {
    for (auto program = cams.programs().cbegin(); program != cams.programs().cend(); ++program) {
        for (auto track = program->cbegin(); track != program->cend(); ++track) {
            for (qsizetype from = 0; from < track->size(); from += kCamsPerRecord) {
                const QList<Cam> chunk = track->mid(from, kCamsPerRecord);
                Writer w;
                w.u16(program.key()).u8(track.key()).u8(int(chunk.size()));
                for (const Cam& cam : chunk) w.i32(cam.on).i32(cam.off);
                appendRecord(blocks, Cams, w.bytes());
            }
        }
    }
}

void appendSettings(QList<QByteArray>& blocks, const QMap<SimSettingKey, Fields>& settings) {
    for (auto it = settings.cbegin(); it != settings.cend(); ++it) {
        const CommandSpec* query = findCommand(kQuery, it.key().first);
        if (!query) continue;
        const Result<QByteArray> data = encodeFields(query->reply, it.value());
        if (!data) {
            qCWarning(commSimLog) << "setting" << it.key().first
                                  << "not stored:" << data.error().message;
            continue;
        }
        Writer w;
        w.u16(quint16(qint16(it.key().second)))
            .u8(int(it.key().first.size()))
            .raw(it.key().first)
            .u8(int(data->size()))
            .raw(*data);
        appendRecord(blocks, Setting, w.bytes());
    }
}

void appendTextLine(QList<QByteArray>& blocks, char kind, int index, int line,
                    const QByteArray& text) {
    Writer w;
    w.u8(kind).u8(index).u8(line).raw(fixedText(text, kTextBytes));
    appendRecord(blocks, TextLine, w.bytes());
}

}  // namespace

int blockLength(quint8 firstByte) {
    return (firstByte >> 4) * 6;
}

QList<QByteArray> serialize(const SimState& state, const SimProfile& profile) {
    QList<QByteArray> blocks{basicBlock(state, profile)};
    appendCams(blocks, state.cams);
    for (auto it = state.deadTimes.cbegin(); it != state.deadTimes.cend(); ++it) {
        appendRecord(blocks, DeadTime, Writer().u8(it.key()).i32(it.value()).bytes());
    }
    for (auto it = state.outputNames.cbegin(); it != state.outputNames.cend(); ++it) {
        appendRecord(blocks, OutputName,
                     Writer().u8(it.key()).raw(fixedText(it.value(), kTextBytes)).bytes());
    }
    for (auto it = state.programNames.cbegin(); it != state.programNames.cend(); ++it) {
        appendRecord(blocks, ProgramName,
                     Writer().u16(it.key()).raw(fixedText(it.value(), kTextBytes)).bytes());
    }
    for (const SimUser& user : state.users) {
        Writer w;
        w.raw(fixedText(user.name, kTextBytes)).raw(fixedText(user.number, kUserNumberBytes));
        w.raw(user.access.leftJustified(SimUser::kAccessBytes, '\0', true))
            .u8(user.allOutputs)
            .u32(user.rights);
        appendRecord(blocks, User, w.bytes());
    }
    for (auto it = state.plcNetworks.cbegin(); it != state.plcNetworks.cend(); ++it) {
        Writer w;
        w.u8(it.key().first).u8(it.key().second).i32(it->value).u16(it->reset);
        for (quint16 symbol : it->symbols) w.u16(symbol);
        appendRecord(blocks, PlcNetwork, w.bytes());
    }
    appendSettings(blocks, state.settings);
    for (auto it = state.userTexts.cbegin(); it != state.userTexts.cend(); ++it) {
        appendTextLine(blocks, kUserText, it.key(), 0, it.value());
    }
    for (auto it = state.plcTexts.cbegin(); it != state.plcTexts.cend(); ++it) {
        for (int line = 0; line < SimState::kPlcTextLines; ++line) {
            appendTextLine(blocks, kPlcText, it.key(), line, it.value()[line]);
        }
    }
    return blocks;
}

namespace {

class Parser {
public:
    Parser(SimState& state, const SimProfile& profile) : m_state(state), m_profile(profile) {}

    // Empty on success, else what is wrong with the record.
    QString record(int type, Reader& r) {
        switch (type) {
            case Cams:
                return cams(r);
            case DeadTime: {
                const int output = r.u8();
                const qint32 value = r.i32();
                if (!validOutput(output))
                    return QStringLiteral("dead time of output %1").arg(output);
                m_state.deadTimes.insert(output, value);
                return {};
            }
            case OutputName: {
                const int output = r.u8();
                if (!validOutput(output)) return QStringLiteral("name of output %1").arg(output);
                m_state.outputNames.insert(output, untilNul(r.raw(kTextBytes)));
                return {};
            }
            case ProgramName: {
                const int program = r.u16();
                if (!validProgram(program))
                    return QStringLiteral("name of program %1").arg(program);
                m_state.programNames.insert(program, untilNul(r.raw(kTextBytes)));
                return {};
            }
            case User: {
                SimUser user;
                user.name = untilNul(r.raw(kTextBytes));
                user.number = untilNul(r.raw(kUserNumberBytes));
                user.access = r.raw(SimUser::kAccessBytes);
                user.allOutputs = r.u8() != 0;
                user.rights = r.u32();
                m_state.users.append(user);
                return {};
            }
            case PlcNetwork: {
                const int area = r.u8();
                const int number = r.u8();
                SimPlcNetwork network;
                network.value = r.i32();
                network.reset = quint16(r.u16());
                for (quint16& symbol : network.symbols) symbol = quint16(r.u16());
                m_state.plcNetworks.insert({area, number}, network);
                return {};
            }
            case Setting:
                return setting(r);
            case TextLine:
                return textLine(r);
            default:
                return QStringLiteral("unknown record type %1").arg(type);
        }
    }

private:
    bool validOutput(int output) const { return output >= 0 && output < m_profile.outputs; }
    bool validProgram(int program) const { return program >= 0 && program < m_profile.programs; }

    QString cams(Reader& r) {
        const int program = r.u16();
        const int output = r.u8();
        const int count = r.u8();
        if (!validProgram(program) || !validOutput(output) || count > kCamsPerRecord) {
            return QStringLiteral("cams of program %1 output %2").arg(program).arg(output);
        }
        for (int i = 0; i < count; ++i) {
            const qint32 on = r.i32();
            const qint32 off = r.i32();
            if (m_state.cams.insert(program, output, {on, off}) != 0) {
                return QStringLiteral("cam %1..%2 of program %3 output %4")
                    .arg(on)
                    .arg(off)
                    .arg(program)
                    .arg(output);
            }
        }
        return {};
    }

    QString setting(Reader& r) {
        const int index = qint16(quint16(r.u16()));
        const QByteArray name = r.raw(r.u8());
        const QByteArray data = r.raw(r.u8());
        const CommandSpec* query = findCommand(kQuery, name);
        if (!query) return QStringLiteral("unknown setting %1").arg(QString::fromLatin1(name));
        Result<Fields> fields = decodeFields(query->reply, data);
        if (!fields)
            return QStringLiteral("setting %1: %2")
                .arg(QString::fromLatin1(name), fields.error().message);
        m_state.settings.insert({name, index}, std::move(fields).value());
        return {};
    }

    QString textLine(Reader& r) {
        const int kind = r.u8();
        const int index = r.u8();
        const int line = r.u8();
        const QByteArray text = untilNul(r.raw(kTextBytes));
        if (kind == kUserText && line == 0) {
            m_state.userTexts.insert(index, text);
        } else if (kind == kPlcText && line < SimState::kPlcTextLines) {
            m_state.plcTexts[index][line] = text;
        } else {
            return QStringLiteral("text line %1/%2/%3").arg(kind).arg(index).arg(line);
        }
        return {};
    }

    SimState& m_state;
    const SimProfile& m_profile;
};

}  // namespace

Result<SimState> parse(const QList<QByteArray>& blocks, const SimProfile& profile) {
    if (blocks.isEmpty() || blocks.first().size() != kBasicBlockBytes) {
        return Error::invalidData(QStringLiteral("EEPROM block 0000 missing or not 128 bytes"));
    }
    Reader basic(blocks.first());
    if (basic.raw(4) != QByteArray(kMagic, 4) || basic.u8() != kLayoutVersion) {
        return Error::invalidData(
            QStringLiteral("EEPROM block 0000 is not from a simulated CamCon"));
    }
    basic.raw(11 + 3 * 2 + 3 * 4);  // identity and capacities: informative only
    SimState state;
    state.cams = SimCamStore(profile.minPosition, profile.maxPosition, profile.camCapacity);
    state.activeProgram = basic.u16();
    if (state.activeProgram >= profile.programs) {
        return Error::invalidData(
            QStringLiteral("active program %1 out of range").arg(state.activeProgram));
    }
    Parser parser(state, profile);
    for (qsizetype i = 1; i < blocks.size(); ++i) {
        const QByteArray& block = blocks.at(i);
        if (block.isEmpty() || blockLength(quint8(block.at(0))) != block.size()) {
            return Error::invalidData(QStringLiteral("EEPROM block %1 has a wrong length").arg(i));
        }
        Reader reader(block.mid(1));
        const QString problem = parser.record(quint8(block.at(0)) & 0x0F, reader);
        if (!problem.isEmpty() || !reader.ok()) {
            return Error::invalidData(
                QStringLiteral("EEPROM block %1: %2")
                    .arg(i)
                    .arg(problem.isEmpty() ? QStringLiteral("record too short") : problem));
        }
    }
    return state;
}

}  // namespace cambench::comm::sim_eeprom
