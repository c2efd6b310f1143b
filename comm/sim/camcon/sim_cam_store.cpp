#include "sim_cam_store.h"

#include <algorithm>
#include <utility>

namespace cambench::comm {

namespace {

// Half-open pieces [from, to) of a cam on the axis [min, max].
QList<std::pair<qint64, qint64>> pieces(const Cam& cam, qint32 min, qint32 max) {
    if (cam.on < cam.off) return {{cam.on, cam.off}};
    return {{cam.on, qint64(max) + 1}, {min, cam.off}};
}

bool byOn(const Cam& a, const Cam& b) {
    return a.on < b.on;
}

}  // namespace

SimCamStore::SimCamStore(qint32 minPosition, qint32 maxPosition, qint32 capacity)
    : m_min(minPosition), m_max(maxPosition), m_capacity(capacity) {}

bool SimCamStore::validCam(const Cam& cam) const {
    return cam.on >= m_min && cam.on <= m_max && cam.off >= m_min && cam.off <= m_max &&
           cam.on != cam.off;
}

bool SimCamStore::overlaps(const Cam& a, const Cam& b) const {
    for (const auto& [aFrom, aTo] : pieces(a, m_min, m_max)) {
        for (const auto& [bFrom, bTo] : pieces(b, m_min, m_max)) {
            if (aFrom < bTo && bFrom < aTo) return true;
        }
    }
    return false;
}

qint32 SimCamStore::checkFits(const QList<Cam>& others, const Cam& cam) const {
    if (!validCam(cam)) return sim_errors::kUnknown;
    for (const Cam& other : others) {
        if (overlaps(other, cam)) return sim_errors::kUnknown;
    }
    return 0;
}

void SimCamStore::setTrack(int program, int output, QList<Cam> cams) {
    if (cams.isEmpty()) {
        auto it = m_programs.find(program);
        if (it == m_programs.end()) return;
        it->remove(output);
        if (it->isEmpty()) m_programs.erase(it);
        return;
    }
    std::sort(cams.begin(), cams.end(), byOn);
    m_programs[program][output] = std::move(cams);
}

qint32 SimCamStore::insert(int program, int output, Cam cam) {
    QList<Cam> cams = track(program, output);
    if (const qint32 error = checkFits(cams, cam)) return error;
    if (camCount() >= m_capacity) return sim_errors::kEepromFull;
    cams.append(cam);
    setTrack(program, output, std::move(cams));
    return 0;
}

qint32 SimCamStore::replaceTrack(int program, int output, const QList<Cam>& cams) {
    QList<Cam> kept;
    for (const Cam& cam : cams) {
        if (const qint32 error = checkFits(kept, cam)) return error;
        kept.append(cam);
    }
    if (camCount() - track(program, output).size() + kept.size() > m_capacity)
        return sim_errors::kEepromFull;
    setTrack(program, output, std::move(kept));
    return 0;
}

qint32 SimCamStore::remove(int program, int output, qint32 on) {
    QList<Cam> cams = track(program, output);
    const auto it =
        std::find_if(cams.begin(), cams.end(), [on](const Cam& c) { return c.on == on; });
    if (it == cams.end()) return sim_errors::kUnknown;
    cams.erase(it);
    setTrack(program, output, std::move(cams));
    return 0;
}

qint32 SimCamStore::change(int program, int output, qint32 oldOn, Cam cam) {
    QList<Cam> cams = track(program, output);
    const auto it =
        std::find_if(cams.begin(), cams.end(), [oldOn](const Cam& c) { return c.on == oldOn; });
    if (it == cams.end()) return sim_errors::kUnknown;
    cams.erase(it);
    if (const qint32 error = checkFits(cams, cam)) return error;
    cams.append(cam);
    setTrack(program, output, std::move(cams));
    return 0;
}

void SimCamStore::removeProgram(int program) {
    m_programs.remove(program);
}

void SimCamStore::copyProgram(int from, int to) {
    if (from == to) return;
    if (m_programs.contains(from)) {
        m_programs.insert(to, m_programs.value(from));
    } else {
        m_programs.remove(to);
    }
}

void SimCamStore::copyTrack(int program, int fromOutput, int toOutput) {
    setTrack(program, toOutput, track(program, fromOutput));
}

QList<Cam> SimCamStore::track(int program, int output) const {
    return m_programs.value(program).value(output);
}

qint32 SimCamStore::camCount() const {
    qint32 count = 0;
    for (const Tracks& tracks : m_programs) {
        for (const QList<Cam>& cams : tracks) count += qint32(cams.size());
    }
    return count;
}

bool SimCamStore::isOn(int program, int output, qint32 position) const {
    const auto programIt = m_programs.constFind(program);
    if (programIt == m_programs.cend()) return false;
    const auto trackIt = programIt->constFind(output);
    if (trackIt == programIt->cend()) return false;
    for (const Cam& cam : *trackIt) {
        for (const auto& [from, to] : pieces(cam, m_min, m_max)) {
            if (position >= from && position < to) return true;
        }
    }
    return false;
}

SimCamCursor::Answer SimCamCursor::at(const QList<Cam>& cams, int index) {
    const int count = int(cams.size());
    m_index = std::clamp(index, -1, count);
    Answer answer;
    answer.earlier = count > 0 && m_index > 0;
    answer.more = count > 0 && m_index < count - 1;
    if (m_index >= 0 && m_index < count) {
        answer.found = true;
        answer.cam = cams.at(m_index);
    }
    return answer;
}

SimCamCursor::Answer SimCamCursor::first(const SimCamStore& store, int program, int output) {
    m_program = program;
    m_output = output;
    return at(store.track(program, output), 0);
}

SimCamCursor::Answer SimCamCursor::last(const SimCamStore& store) {
    const QList<Cam> cams = store.track(m_program, m_output);
    return at(cams, int(cams.size()) - 1);
}

SimCamCursor::Answer SimCamCursor::next(const SimCamStore& store) {
    const QList<Cam> cams = store.track(m_program, m_output);
    return at(cams, std::min(m_index, int(cams.size())) + 1);
}

SimCamCursor::Answer SimCamCursor::previous(const SimCamStore& store) {
    const QList<Cam> cams = store.track(m_program, m_output);
    return at(cams, std::min(m_index, int(cams.size())) - 1);
}

SimCamCursor::Answer SimCamCursor::search(const SimCamStore& store, qint32 fromOn) {
    const QList<Cam> cams = store.track(m_program, m_output);
    const auto it =
        std::find_if(cams.begin(), cams.end(), [fromOn](const Cam& c) { return c.on >= fromOn; });
    return at(cams, int(it - cams.begin()));
}

}  // namespace cambench::comm
