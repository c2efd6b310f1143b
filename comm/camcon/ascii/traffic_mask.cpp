#include "traffic_mask.h"

#include "catalogue.h"
#include "frame.h"

#include <QList>

#include <limits>
#include <utility>

namespace cambench::comm {

namespace {

using Range = std::pair<int, int>;  // [begin, end) in the unescaped body
// A range that runs up to the checksum.
constexpr int kToChecksum = std::numeric_limits<int>::max();
// "EE" and the block number: what follows is the block's data (notes 6).
constexpr int kEepromDataOffset = 2 + 4;

// Characters a field takes in the unescaped body; -1 when it runs to the end.
int fieldLength(const FieldSpec& field) {
    switch (field.type) {
        case FieldType::Hex:
        case FieldType::SignedHex:
        case FieldType::Text:
        case FieldType::Binary:
            return field.width;
        case FieldType::HexWords:
            return field.width * field.count;
        case FieldType::TextRest:
        case FieldType::HexBytes:
            return -1;
    }
    return -1;
}

bool isSecret(const FieldSpec& field) {
    return field.type == FieldType::Text && QByteArray(field.name).toLower().contains("number");
}

QList<Range> secretRanges(const CommandSpec& spec, const QList<FieldSpec>& fields) {
    QList<Range> ranges;
    int offset = int(qstrlen(spec.name));
    for (const FieldSpec& field : fields) {
        const int length = fieldLength(field);
        if (length < 0) break;
        if (isSecret(field)) ranges.append({offset, offset + length});
        offset += length;
    }
    return ranges;
}

// The data of an EEPROM block: !EE requests and :EE replies, but not the
// acknowledgement (:EEOK), an error (:EEERR...) or a block number alone.
QList<Range> eepromRanges(char lead, QByteArrayView body, bool outgoing) {
    if (lead != (outgoing ? kCommand : kReply)) return {};
    const QByteArrayView rest = body.sliced(2);
    if (!outgoing && (rest.startsWith("OK") || rest.startsWith("ERR"))) return {};
    return {{kEepromDataOffset, kToChecksum}};
}

// The ranges for the frame with this lead and body start, none for others.
QList<Range> rangesFor(char lead, QByteArrayView body, bool outgoing) {
    if (body.startsWith(QByteArrayView("EE"))) return eepromRanges(lead, body, outgoing);
    if (!body.startsWith(QByteArrayView("USER"))) return {};
    if (outgoing && lead == kCommand) {
        if (const CommandSpec* spec = findCommand(kCommand, "USER"))
            return secretRanges(*spec, spec->request);
    } else if (!outgoing && lead == kReply) {
        if (const CommandSpec* spec = findCommand(kQuery, "USER"))
            return secretRanges(*spec, spec->reply);
    }
    return {};
}

bool inRanges(const QList<Range>& ranges, int index) {
    for (const auto& [begin, end] : ranges)
        if (index >= begin && index < end) return true;
    return false;
}

// Multiuser header bytes are >= 0x40, so the first lead character is the
// frame's lead; -1 when there is none.
qsizetype leadIndex(const QByteArray& wire) {
    for (qsizetype i = 0; i < wire.size(); ++i)
        if (wire[i] == kQuery || wire[i] == kCommand || wire[i] == kReply) return i;
    return -1;
}

// The first CR not escaped by ESC after `from`; -1 when there is none.
qsizetype frameEnd(const QByteArray& wire, qsizetype from) {
    for (qsizetype i = from; i < wire.size(); ++i) {
        if (wire[i] == kEsc) {
            ++i;
        } else if (wire[i] == kCr) {
            return i;
        }
    }
    return -1;
}

}  // namespace

QByteArray maskSecrets(QByteArray wire, bool outgoing) {
    const qsizetype lead = leadIndex(wire);
    if (lead < 0) return wire;
    const QList<Range> ranges =
        rangesFor(wire[lead], QByteArrayView(wire).sliced(lead + 1), outgoing);
    if (ranges.isEmpty()) return wire;

    // Only a whole frame (CR LF) shows its checksum; in anything less the
    // characters before a CR may be data.
    const qsizetype cr = frameEnd(wire, lead + 1);
    const bool whole = cr >= 0 && cr + 1 < wire.size() && wire[cr + 1] == kLf;
    const qsizetype end = whole ? cr - 2 : wire.size();
    int bodyIndex = 0;
    for (qsizetype i = lead + 1; i < end; ++bodyIndex) {
        const int width = (wire[i] == kEsc && i + 1 < wire.size()) ? 2 : 1;
        if (inRanges(ranges, bodyIndex))
            for (int k = 0; k < width && i + k < wire.size(); ++k) wire[i + k] = '*';
        i += width;
    }
    return wire;
}

bool isSecretReply(const QByteArray& wire) {
    const qsizetype lead = leadIndex(wire);
    if (lead < 0 || wire[lead] != kReply) return false;
    const QByteArrayView body = QByteArrayView(wire).sliced(lead + 1);
    return body.startsWith("EE") || body.startsWith("USER");
}

QByteArray maskAll(QByteArray wire) {
    for (char& c : wire)
        if (c != kCr && c != kLf) c = '*';
    return wire;
}

}  // namespace cambench::comm
