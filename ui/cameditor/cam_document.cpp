#include "ui/cameditor/cam_document.h"

#include "ui/cameditor/cam_commands.h"

#include <QUndoStack>

#include <algorithm>

namespace cambench {

namespace {

Track trackOf(const CamProgram& program, int output) {
    Track track = program.tracks.value(output);
    track.output = output;
    return track;
}

ChangeState compare(bool deviceKnown, bool equal) {
    if (!deviceKnown) {
        return ChangeState::PcOnly;
    }
    return equal ? ChangeState::Unchanged : ChangeState::Edited;
}

}  // namespace

CamDocument::CamDocument(QObject* parent) : QObject(parent), m_undoStack(new QUndoStack(this)) {}

CamDocument::~CamDocument() = default;

void CamDocument::setLimits(const DeviceInfo& info, bool rotary) {
    m_info = info;
    m_rotary = rotary;
    Q_EMIT limitsChanged();
}

CamProgram CamDocument::program(int number) const {
    CamProgram program = m_edited.value(number);
    program.number = number;
    return program;
}

Track CamDocument::track(int program, int output) const {
    return trackOf(m_edited.value(program), output);
}

QString CamDocument::programName(int program) const { return m_edited.value(program).name; }

QString CamDocument::outputName(int output) const { return m_names.outputs.value(output); }

qint32 CamDocument::deadTime(int output) const { return m_deadTimes.value(output); }

void CamDocument::loadProgramFromDevice(const CamProgram& program) {
    const CamProgram clean = normalized(program);
    m_device.insert(clean.number, clean);
    m_edited.insert(clean.number, clean);
    // Commands recorded against the replaced state would undo into a mix of
    // old edits and fresh device data.
    m_undoStack->clear();
    Q_EMIT programChanged(clean.number);
    Q_EMIT deviceStateChanged();
    notifyChangedCount();
}

void CamDocument::loadOutputSettingsFromDevice(const QMap<int, QString>& outputNames,
                                               const DeadTimes& deadTimes) {
    m_names.outputs = outputNames;
    m_deviceOutputNames = outputNames;
    m_deadTimes = deadTimes;
    m_deviceDeadTimes = deadTimes;
    m_outputSettingsKnown = true;
    for (int output = 1; output <= m_info.outputs; ++output) {
        Q_EMIT outputNameChanged(output);
        Q_EMIT deadTimeChanged(output);
    }
    Q_EMIT deviceStateChanged();
    notifyChangedCount();
}

void CamDocument::loadOffline(const QMap<int, CamProgram>& programs, const Names& names,
                              const DeadTimes& deadTimes) {
    m_undoStack->clear();
    m_edited.clear();
    for (const CamProgram& program : programs) {
        applyProgram(program);
    }
    m_names.outputs = names.outputs;
    m_deadTimes = deadTimes;
    for (auto it = names.programs.cbegin(); it != names.programs.cend(); ++it) {
        if (m_edited.contains(it.key()) || !it.value().isEmpty()) {
            m_edited[it.key()].number = it.key();
            m_edited[it.key()].name = it.value();
        }
    }
    for (int number = 0; number < m_info.programs; ++number) {
        Q_EMIT programChanged(number);
    }
    for (int output = 1; output <= m_info.outputs; ++output) {
        Q_EMIT outputNameChanged(output);
        Q_EMIT deadTimeChanged(output);
    }
    Q_EMIT deviceStateChanged();
    notifyChangedCount();
}

void CamDocument::markWritten(int program) {
    m_device.insert(program, this->program(program));
    Q_EMIT deviceStateChanged();
    notifyChangedCount();
}

void CamDocument::markOutputSettingsWritten() {
    m_deviceOutputNames = m_names.outputs;
    m_deviceDeadTimes = m_deadTimes;
    m_outputSettingsKnown = true;
    Q_EMIT deviceStateChanged();
    notifyChangedCount();
}

void CamDocument::markTrackWritten(int program, int output) {
    CamProgram& device = m_device[program];
    device.number = program;
    const Track edited = track(program, output);
    if (edited.cams.isEmpty()) {
        device.tracks.remove(output);
    } else {
        device.tracks.insert(output, edited);
    }
    Q_EMIT deviceStateChanged();
    notifyChangedCount();
}

void CamDocument::markProgramNameWritten(int program) {
    m_device[program].number = program;
    m_device[program].name = programName(program);
    Q_EMIT deviceStateChanged();
    notifyChangedCount();
}

void CamDocument::markOutputNameWritten(int output) {
    m_deviceOutputNames.insert(output, outputName(output));
    Q_EMIT deviceStateChanged();
    notifyChangedCount();
}

void CamDocument::markDeadTimeWritten(int output) {
    m_deviceDeadTimes.insert(output, deadTime(output));
    Q_EMIT deviceStateChanged();
    notifyChangedCount();
}

ChangeState CamDocument::programState(int program) const {
    return compare(m_device.contains(program), this->program(program) == m_device.value(program));
}

ChangeState CamDocument::trackState(int program, int output) const {
    return compare(m_device.contains(program),
                   track(program, output).cams == trackOf(m_device.value(program), output).cams);
}

ChangeState CamDocument::camState(int program, int output, int index) const {
    const QList<Cam> cams = track(program, output).cams;
    const bool onDevice = index >= 0 && index < cams.size() &&
                          trackOf(m_device.value(program), output).cams.contains(cams.at(index));
    return compare(m_device.contains(program), onDevice);
}

QList<TrackDifference> CamDocument::differences() const {
    QList<TrackDifference> result;
    QList<int> programs = m_edited.keys() + m_device.keys();
    std::sort(programs.begin(), programs.end());
    programs.erase(std::unique(programs.begin(), programs.end()), programs.end());
    for (int number : programs) {
        const CamProgram edited = program(number);
        const CamProgram device = m_device.value(number);
        QList<int> outputs = edited.tracks.keys() + device.tracks.keys();
        std::sort(outputs.begin(), outputs.end());
        outputs.erase(std::unique(outputs.begin(), outputs.end()), outputs.end());
        for (int output : outputs) {
            TrackDifference difference{number, output, m_device.contains(number),
                                       trackOf(device, output), trackOf(edited, output)};
            if (difference.deviceTrack != difference.editedTrack) {
                result.append(difference);
            }
        }
    }
    return result;
}

int CamDocument::changedCount() const {
    int count = int(differences().size());
    for (auto it = m_edited.cbegin(); it != m_edited.cend(); ++it) {
        if (it->name != m_device.value(it.key()).name) {
            ++count;
        }
    }
    for (int output = 1; output <= m_info.outputs; ++output) {
        count += int(m_names.outputs.value(output) != m_deviceOutputNames.value(output));
        count += int(m_deadTimes.value(output) != m_deviceDeadTimes.value(output));
    }
    return count;
}

quint64 CamDocument::newDragKey() { return ++m_lastDragKey; }

void CamDocument::setCam(int program, int output, int index, const Cam& cam, quint64 mergeKey) {
    const Track before = track(program, output);
    if (index < 0 || index >= before.cams.size() || before.cams.at(index) == cam) {
        return;
    }
    Track after = before;
    after.cams[index] = cam;
    m_undoStack->push(new SetCamCommand(this, program, before, normalized(after),
                                        tr("Change cam on output %1").arg(output), mergeKey));
}

void CamDocument::insertCam(int program, int output, const Cam& cam) {
    const Track before = track(program, output);
    Track after = before;
    after.cams.append(cam);
    m_undoStack->push(new ReplaceTrackCommand(this, program, before, normalized(after),
                                              tr("Add cam to output %1").arg(output)));
}

void CamDocument::deleteCam(int program, int output, int index) {
    const Track before = track(program, output);
    if (index < 0 || index >= before.cams.size()) {
        return;
    }
    Track after = before;
    after.cams.removeAt(index);
    m_undoStack->push(new ReplaceTrackCommand(this, program, before, after,
                                              tr("Delete cam of output %1").arg(output)));
}

void CamDocument::replaceTrack(int program, const Track& track, const QString& text) {
    const Track before = this->track(program, track.output);
    const Track after = normalized(track);
    if (before != after) {
        m_undoStack->push(new ReplaceTrackCommand(this, program, before, after, text));
    }
}

void CamDocument::copyTrack(int program, int fromOutput, int toProgram, int toOutput) {
    Track copy = track(program, fromOutput);
    copy.output = toOutput;
    const Track before = track(toProgram, toOutput);
    if (before != copy) {
        m_undoStack->push(new ReplaceTrackCommand(
            this, toProgram, before, copy,
            tr("Copy output %1 to output %2 of program %3").arg(fromOutput).arg(toOutput).arg(toProgram)));
    }
}

void CamDocument::copyProgram(int from, int to) {
    CamProgram copy = program(from);
    copy.number = to;
    const CamProgram before = program(to);
    if (before != copy) {
        m_undoStack->push(new ReplaceProgramCommand(
            this, before, copy, tr("Copy program %1 to program %2").arg(from).arg(to)));
    }
}

void CamDocument::generateCams(int program, const Track& track) {
    replaceTrack(program, track, tr("Generate cams on output %1").arg(track.output));
}

void CamDocument::replaceTracks(int program, const QMap<int, Track>& tracks,
                                const QString& text) {
    CamProgram after = this->program(program);
    after.tracks = tracks;
    after = normalized(after);
    const CamProgram before = this->program(program);
    if (before != after) {
        m_undoStack->push(new ReplaceProgramCommand(this, before, after, text));
    }
}

void CamDocument::setProgramName(int program, const QString& name) {
    const QString before = programName(program);
    if (before == name) {
        return;
    }
    m_undoStack->push(new SetValueCommand<QString>(
        before, name, [this, program](const QString& value) { applyProgramName(program, value); },
        tr("Rename program %1").arg(program)));
}

void CamDocument::setOutputName(int output, const QString& name) {
    const QString before = outputName(output);
    if (before == name) {
        return;
    }
    m_undoStack->push(new SetValueCommand<QString>(
        before, name, [this, output](const QString& value) { applyOutputName(output, value); },
        tr("Rename output %1").arg(output)));
}

void CamDocument::setDeadTime(int output, qint32 deadTime) {
    const qint32 before = this->deadTime(output);
    if (before == deadTime) {
        return;
    }
    m_undoStack->push(new SetValueCommand<qint32>(
        before, deadTime, [this, output](const qint32& value) { applyDeadTime(output, value); },
        tr("Change dead time of output %1").arg(output)));
}

void CamDocument::applyTrack(int program, const Track& track) {
    CamProgram& target = m_edited[program];
    target.number = program;
    if (track.cams.isEmpty()) {
        target.tracks.remove(track.output);
    } else {
        target.tracks.insert(track.output, track);
    }
    Q_EMIT trackChanged(program, track.output);
    notifyChangedCount();
}

void CamDocument::applyProgram(const CamProgram& program) {
    const CamProgram clean = normalized(program);
    m_edited.insert(clean.number, clean);
    Q_EMIT programChanged(clean.number);
    notifyChangedCount();
}

void CamDocument::applyProgramName(int program, const QString& name) {
    m_edited[program].number = program;
    m_edited[program].name = name;
    Q_EMIT programChanged(program);
    notifyChangedCount();
}

void CamDocument::applyOutputName(int output, const QString& name) {
    m_names.outputs.insert(output, name);
    Q_EMIT outputNameChanged(output);
    notifyChangedCount();
}

void CamDocument::applyDeadTime(int output, qint32 deadTime) {
    m_deadTimes.insert(output, deadTime);
    Q_EMIT deadTimeChanged(output);
    notifyChangedCount();
}

Track CamDocument::normalized(Track track) {
    normaliseTrack(track);
    return track;
}

CamProgram CamDocument::normalized(CamProgram program) {
    normaliseProgram(program);
    return program;
}

QList<CamProblem> CamDocument::problems(int program, int output) const {
    return validateTrack(track(program, output), program, m_info, m_rotary);
}

Cam CamDocument::suggestNewCam(int program, int output) const {
    const Axis axis = this->axis();
    constexpr int kSuggestedCamsPerAxis = 36;
    const qint64 length = std::max<qint64>(axis.span() / kSuggestedCamsPerAxis, 1);
    Track candidate = track(program, output);
    candidate.cams.append(Cam{});
    QList<qint64> starts{axis.min};
    for (const Cam& cam : track(program, output).cams) {
        starts.append(cam.off);  // right after an existing cam first
    }
    for (qint64 on = axis.min; on + length <= axis.max; on += length) {
        starts.append(on);
    }
    for (qint64 on : starts) {
        if (on + length > qint64(axis.max) + (axis.rotary ? 1 : 0)) {
            continue;
        }
        candidate.cams.last() = {qint32(on), axis.wrap(on + length)};
        if (validateTrack(candidate, program, m_info, m_rotary).isEmpty()) {
            return candidate.cams.last();
        }
    }
    return {axis.min, axis.moved(axis.min, length)};
}

void CamDocument::notifyChangedCount() {
    const int count = changedCount();
    if (count != m_lastChangedCount) {
        m_lastChangedCount = count;
        Q_EMIT changedCountChanged(count);
    }
}

}  // namespace cambench
