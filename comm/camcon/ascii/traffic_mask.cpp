#include "traffic_mask.h"

#include "catalogue.h"
#include "frame.h"

#include <QList>

#include <utility>

namespace cambench::comm {

namespace {

using Range = std::pair<int, int>;  // [begin, end) in the unescaped body

// Characters a field takes in the unescaped body; -1 when it runs to the end.
int fieldLength(const FieldSpec& field) {
    switch (field.type) {
    case FieldType::Hex:
    case FieldType::SignedHex:
    case FieldType::Text:
    case FieldType::Binary: return field.width;
    case FieldType::HexWords: return field.width * field.count;
    case FieldType::TextRest:
    case FieldType::HexBytes: return -1;
    }
    return -1;
}

bool isSecret(const FieldSpec& field) {
    return field.type == FieldType::Text &&
           QByteArray(field.name).toLower().contains("number");
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

// The ranges for the frame with this lead and body start, none for others.
QList<Range> rangesFor(char lead, QByteArrayView body, bool outgoing) {
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

}  // namespace

QByteArray maskSecrets(QByteArray wire, bool outgoing) {
    // Multiuser header bytes are >= 0x40, so the first lead character is the
    // frame's lead.
    qsizetype lead = -1;
    for (qsizetype i = 0; i < wire.size() && lead < 0; ++i)
        if (wire[i] == kQuery || wire[i] == kCommand || wire[i] == kReply) lead = i;
    if (lead < 0) return wire;
    const QList<Range> ranges =
        rangesFor(wire[lead], QByteArrayView(wire).sliced(lead + 1), outgoing);
    if (ranges.isEmpty()) return wire;

    int bodyIndex = 0;
    for (qsizetype i = lead + 1; i < wire.size(); ++bodyIndex) {
        if (wire[i] == kCr) break;
        const int width = (wire[i] == kEsc && i + 1 < wire.size()) ? 2 : 1;
        if (inRanges(ranges, bodyIndex))
            for (int k = 0; k < width; ++k) wire[i + k] = '*';
        i += width;
    }
    return wire;
}

}  // namespace cambench::comm
