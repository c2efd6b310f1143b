#include "sim_table_areas.h"

#include "comm/camcon/table/table_map.h"
#include "comm/sim/camcon/sim_device.h"

namespace cambench::comm {

using table::Rk512Error;

namespace {

enum class Group { Track, Status, Setting, Plc, None };

Group groupOf(const SimDevice& device, int area) {
    if (sim_table::isTrackArea(device, area)) return Group::Track;
    if (area == table::kStatusArea || area == table::kIoArea) return Group::Status;
    if (area >= table::kSystemArea && area <= table::kConfigArea) return Group::Setting;
    if ((area >= table::kFirstPlcSetValueArea && area < table::kMultiCamArea) ||
        area == table::kPlcLinkArea)
        return Group::Plc;
    return Group::None;
}

SimAreaReply noArea(int area) {
    return SimAreaReply::fail(Rk512Error::BeyondBlock,
                              QStringLiteral("data area %1 is not simulated").arg(area));
}

}  // namespace

SimAreaReply SimTableAreas::read(int area, int firstWord, int count) {
    const Group group = groupOf(m_device, area);
    if (group == Group::None) return noArea(area);
    SimAreaReply reply;
    for (int word = firstWord; word < firstWord + count; ++word) {
        sim_table::WordRead read;
        switch (group) {
            case Group::Track:
                read = sim_table::readTrackWord(m_device, area, word);
                break;
            case Group::Status:
                read = sim_table::readStatusWord(m_device, area, word);
                break;
            case Group::Setting:
                read = sim_table::readSettingWord(m_device, area, word);
                break;
            case Group::Plc:
                read = sim_table::readPlcWord(m_device, area, word);
                break;
            case Group::None:
                break;
        }
        if (read.error != Rk512Error::None) return SimAreaReply::fail(read.error, read.detail);
        reply.words.append(read.value);
    }
    return reply;
}

SimAreaReply SimTableAreas::write(int area, int firstWord, const QList<qint32>& values) {
    const Group group = groupOf(m_device, area);
    if (group == Group::None) return noArea(area);
    if (group == Group::Track) return sim_table::writeTrackWords(m_device, area, firstWord, values);
    // Word by word, in order; an error stops the run where it is.
    for (int i = 0; i < values.size(); ++i) {
        const int word = firstWord + i;
        SimAreaReply reply;
        if (group == Group::Status) {
            reply = sim_table::writeStatusWord(m_device, area, word, values.at(i));
        } else if (group == Group::Setting) {
            reply = sim_table::writeSettingWord(m_device, area, word, values.at(i));
        } else {
            reply = sim_table::writePlcWord(m_device, area, word, values.at(i));
        }
        if (reply.error != Rk512Error::None || reply.silent) return reply;
    }
    return {};
}

}  // namespace cambench::comm
