// Areas 1..200 (cams and dead times of an output in the programming
// program) and 241..254 (analogue cams), manual 3.1 and 3.19.
#include "sim_table_areas.h"

#include "comm/camcon/table/cam_track_words.h"
#include "comm/camcon/table/table_map.h"
#include "comm/sim/camcon/sim_device.h"
#include "comm/sim/sim_log.h"

#include <algorithm>

namespace cambench::comm::sim_table {

using table::kEmptyCamWord;
using table::Rk512Error;

namespace {

constexpr int kLastPairWord = 2 * table::kMaxTrackCams;  // 250

bool isAnalogueArea(int area) {
    return area >= table::kFirstAnalogCamArea && area <= table::kLastAnalogCamArea;
}

// A pair of words as the device keeps it: cams by switch-on point,
// analogue base points by position.
using Pair = std::pair<qint32, qint32>;

QList<Pair> pairsOf(SimDevice& device, int area) {
    QList<Pair> pairs;
    if (isAnalogueArea(area)) {
        for (const AnaloguePoint& point :
             device.tableState().analogueCams.value(area - table::kFirstAnalogCamArea))
            pairs.append({point.position, point.value});
    } else {
        for (const Cam& cam : device.state().cams.track(programmingProgram(device), area - 1))
            pairs.append({cam.on, cam.off});
    }
    return pairs;
}

SimAreaReply refused(const QString& detail) {
    qCDebug(commSimLog) << "table write refused:" << detail;
    return SimAreaReply::fail(Rk512Error::General, detail);
}

// The analogue base points become `pairs` (ordered by position, none twice).
SimAreaReply setAnaloguePoints(SimDevice& device, int area, QList<Pair> pairs) {
    const SimProfile& profile = device.profile();
    std::sort(pairs.begin(), pairs.end());
    QList<AnaloguePoint> points;
    for (const Pair& pair : pairs) {
        if (pair.first < profile.minPosition || pair.first > profile.maxPosition ||
            pair.second < kMinAnalogueValue || pair.second > kMaxAnalogueValue ||
            (!points.isEmpty() && points.last().position == pair.first))
            return refused(
                QStringLiteral("analogue base point %1/%2").arg(pair.first).arg(pair.second));
        points.append({pair.first, pair.second});
    }
    const int channel = area - table::kFirstAnalogCamArea;
    if (points.isEmpty()) {
        device.tableState().analogueCams.remove(channel);
    } else {
        device.tableState().analogueCams.insert(channel, points);
    }
    return {};
}

// The cams become `pairs` (the store checks range, overlap and room).
SimAreaReply setCams(SimDevice& device, int area, const QList<Pair>& pairs) {
    QList<Cam> cams;
    for (const Pair& pair : pairs) cams.append({pair.first, pair.second});
    const qint32 error =
        device.state().cams.replaceTrack(programmingProgram(device), area - 1, cams);
    if (error != 0)
        return refused(QStringLiteral("cams of area %1: error %2").arg(area).arg(error));
    return {};
}

// Manual 3.1: from place 1, two or more pairs replace the whole track;
// otherwise each pair changes its place, creates a cam in an empty place,
// or (equal points, or the empty value) deletes the cam there.
SimAreaReply writePairs(SimDevice& device, int area, int firstWord, const QList<qint32>& values) {
    if (firstWord % 2 != 1 || values.size() % 2 != 0)
        return refused(QStringLiteral("on and off points must travel together"));
    const bool analogue = isAnalogueArea(area);
    const auto set = [&](const QList<Pair>& pairs) {
        return analogue ? setAnaloguePoints(device, area, pairs) : setCams(device, area, pairs);
    };
    const auto removes = [analogue](const Pair& pair) {
        return pair.first == kEmptyCamWord || (!analogue && pair.first == pair.second);
    };
    const int firstPlace = (firstWord + 1) / 2;
    QList<Pair> written;
    for (int i = 0; i < values.size(); i += 2) written.append({values.at(i), values.at(i + 1)});
    if (firstPlace == 1 && written.size() >= 2) {
        QList<Pair> kept;
        for (const Pair& pair : written)
            if (!removes(pair)) kept.append(pair);
        return set(kept);
    }
    QList<Pair> pairs = pairsOf(device, area);
    for (int i = 0; i < written.size(); ++i) {
        const int place = firstPlace + i;  // 1-based
        const Pair& pair = written.at(i);
        if (removes(pair)) {
            if (place <= pairs.size()) pairs.removeAt(place - 1);
        } else if (place <= pairs.size()) {
            pairs[place - 1] = pair;
        } else {
            pairs.append(pair);
        }
    }
    return set(pairs);
}

SimAreaReply writeDeadTimeWord(SimDevice& device, int area, int word, qint32 value) {
    const int output = area - 1;
    const qint32 maxDeadTime = device.profile().maxDeadTime;
    if (word == table::tableWord(u"track.dead_time")) {
        if (value < 0 || value > maxDeadTime)
            return refused(QStringLiteral("dead time %1").arg(value));
        if (value == 0) {
            device.state().deadTimes.remove(output);
        } else {
            device.state().deadTimes.insert(output, value);
        }
        return {};
    }
    OutputDeadTime& modes = device.tableState().deadTimeModes[output];
    if (word == table::tableWord(u"track.dead_time_mode")) {
        const std::optional<DeadTimeMode> mode = deadTimeModeFromNumber(value);
        if (!mode) return refused(QStringLiteral("dead-time mode %1").arg(value));
        modes.mode = *mode;
        return {};
    }
    if (value < 0 || value > maxDeadTime) return refused(QStringLiteral("dead time %1").arg(value));
    (word == table::tableWord(u"track.dead_time_on") ? modes.on : modes.off) = value;
    return {};
}

}  // namespace

int programmingProgram(const SimDevice& device) {
    const int program = device.tableState().programmingProgram;
    return program < 0 ? device.state().activeProgram : program;
}

bool isTrackArea(const SimDevice& device, int area) {
    if (area >= table::kFirstTrackArea && area <= table::kLastTrackArea)
        return area <= device.profile().outputs;
    if (isAnalogueArea(area))
        return area - table::kFirstAnalogCamArea < device.profile().analogChannels;
    return false;
}

WordRead readTrackWord(SimDevice& device, int area, int word) {
    const bool analogue = isAnalogueArea(area);
    if (word >= table::kFirstCamWord && word <= kLastPairWord) {
        const QList<Pair> pairs = pairsOf(device, area);
        const int place = (word + 1) / 2;
        if (place > pairs.size()) return {kEmptyCamWord, Rk512Error::None, {}};
        const Pair& pair = pairs.at(place - 1);
        return {word % 2 == 1 ? pair.first : pair.second, Rk512Error::None, {}};
    }
    if (word == table::tableWord(u"track.cam_count"))
        return {qint32(pairsOf(device, area).size()), Rk512Error::None, {}};
    if (analogue) return {0, Rk512Error::None, {}};
    const int output = area - 1;
    const OutputDeadTime modes = device.tableState().deadTimeModes.value(output);
    if (word == table::tableWord(u"track.dead_time"))
        return {device.state().deadTimes.value(output), Rk512Error::None, {}};
    if (word == table::tableWord(u"track.dead_time_mode"))
        return {qint32(modes.mode), Rk512Error::None, {}};
    if (word == table::tableWord(u"track.dead_time_on")) return {modes.on, Rk512Error::None, {}};
    if (word == table::tableWord(u"track.dead_time_off")) return {modes.off, Rk512Error::None, {}};
    return {0, Rk512Error::None, {}};
}

SimAreaReply writeTrackWords(SimDevice& device, int area, int firstWord,
                             const QList<qint32>& values) {
    int word = firstWord;
    qsizetype at = 0;
    while (at < values.size()) {
        if (word >= table::kFirstCamWord && word <= kLastPairWord) {
            const qsizetype pairWords =
                std::min<qsizetype>(values.size() - at, kLastPairWord + 1 - word);
            const SimAreaReply reply = writePairs(device, area, word, values.mid(at, pairWords));
            if (reply.error != Rk512Error::None) return reply;
            word += int(pairWords);
            at += pairWords;
            continue;
        }
        if (isAnalogueArea(area) || word == table::tableWord(u"track.cam_count") || word > 253) {
            // Word 254 shifts every cam: a relative change the simulator lacks.
            return refused(
                QStringLiteral("word %1 of area %2 cannot be written").arg(word).arg(area));
        }
        const SimAreaReply reply = writeDeadTimeWord(device, area, word, values.at(at));
        if (reply.error != Rk512Error::None) return reply;
        ++word;
        ++at;
    }
    return {};
}

}  // namespace cambench::comm::sim_table
