#include "ui/camcon/cameditor/cam_document.h"

#include "ui/camcon/cameditor/cam_commands.h"

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
        return ChangeState::NotRead;
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

QString CamDocument::programName(int program) const {
    return m_edited.value(program).name;
}

QString CamDocument::outputName(int output) const {
    return m_names.outputs.value(output);
}

qint32 CamDocument::deadTime(int output) const {
    return m_deadTimes.value(output);
}

void CamDocument::mergeProgram(const CamProgram& incoming, bool fromDevice, bool keepEdits) {
    const int number = incoming.number;
    const CamProgram clean = normalized(incoming);
    const CamProgram before = program(number);
    const std::optional<CamProgram> oldDevice = deviceProgram(number);
    const bool hadEdits = programEdited(number);
    CamProgram after = clean;
    // Items carried from another device: those, and only those, are edits.
    const bool carried = !oldDevice && carryEdits(number);
    if (keepEdits && hadEdits) {
        // Item by item: what differs from the old device copy is an edit.
        QList<int> outputs = before.tracks.keys() + clean.tracks.keys();
        if (oldDevice) outputs += oldDevice->tracks.keys();
        for (int output : outputs) {
            if (carried && !carriedTrack(number, output)) continue;
            const Track mine = trackOf(before, output);
            if (oldDevice && mine.cams == trackOf(*oldDevice, output).cams) continue;
            if (mine.cams.isEmpty()) {
                after.tracks.remove(output);
            } else {
                after.tracks.insert(output, mine);
            }
        }
        if (carried ? m_carriedProgramNames.contains(number)
                    : !oldDevice || before.name != oldDevice->name)
            after.name = before.name;
    }
    if (fromDevice || !keepEdits) {
        // The carried items met this device's values: edits from now on.
        m_carriedProgramNames.remove(number);
        for (int output = 1; output <= m_info.outputs; ++output)
            m_carriedTracks.remove(trackKey(number, output));
    }
    if (fromDevice) {
        m_device.insert(number, clean);
        forgetUnknownTracks(number);
    }
    if (after != before && hadEdits && !keepEdits) {
        // The edits are replaced as one undo step: the history stays whole.
        m_undoStack->push(new ReplaceProgramCommand(
            this, before, after,
            fromDevice ? tr("Take program %1 from the device").arg(number)
                       : tr("Take program %1 from the file").arg(number)));
    } else if (after != before || !m_edited.contains(number)) {
        applyProgram(after);
    }
    Q_EMIT deviceStateChanged();
    notifyChangedCount();
}

void CamDocument::clear() {
    m_undoStack->clear();
    m_edited.clear();
    m_device.clear();
    m_unknownTracks.clear();
    m_carriedTracks.clear();
    m_carriedProgramNames.clear();
    m_carriedOutputNames.clear();
    m_carriedDeadTimes.clear();
    m_names = {};
    m_deadTimes.clear();
    m_deviceOutputNames.clear();
    m_deviceDeadTimes.clear();
    m_outputSettingsKnown = false;
    setMinimumPulses({});
    for (int number = 0; number < m_info.programs; ++number) Q_EMIT programChanged(number);
    for (int output = 1; output <= m_info.outputs; ++output) {
        Q_EMIT outputNameChanged(output);
        Q_EMIT deadTimeChanged(output);
    }
    Q_EMIT deviceStateChanged();
    notifyChangedCount();
}

bool CamDocument::programEdited(int program) const {
    if (carryEdits(program)) return true;
    if (!m_edited.contains(program)) return false;
    const CamProgram edited = this->program(program);
    if (!m_device.contains(program)) return !edited.tracks.isEmpty() || !edited.name.isEmpty();
    return edited.tracks != m_device.value(program).tracks ||
           edited.name != m_device.value(program).name;
}

void CamDocument::mergeOutputSettings(const QMap<int, QString>& outputNames,
                                      const DeadTimes& deadTimes, bool fromDevice, bool keepEdits) {
    QMap<int, QString> names = outputNames;
    DeadTimes times = deadTimes;
    const bool edited = outputSettingsEditCount() > 0;
    for (int output = 1; output <= m_info.outputs; ++output) {
        const bool nameEdited = m_carriedOutputNames.contains(output) ||
                                m_names.outputs.value(output) != m_deviceOutputNames.value(output);
        const bool timeEdited = m_carriedDeadTimes.contains(output) ||
                                m_deadTimes.value(output) != m_deviceDeadTimes.value(output);
        if (keepEdits && nameEdited) names.insert(output, m_names.outputs.value(output));
        if (keepEdits && timeEdited) times.insert(output, m_deadTimes.value(output));
    }
    if (fromDevice || !keepEdits) {
        m_carriedOutputNames.clear();
        m_carriedDeadTimes.clear();
    }
    if (fromDevice) {
        m_deviceOutputNames = outputNames;
        m_deviceDeadTimes = deadTimes;
        m_outputSettingsKnown = true;
    }
    if (edited && !keepEdits) m_undoStack->beginMacro(tr("Take names and dead times"));
    for (int output = 1; output <= m_info.outputs; ++output) {
        if (edited && !keepEdits) {
            setOutputName(output, names.value(output));
            setDeadTime(output, times.value(output));
        } else {
            if (m_names.outputs.value(output) != names.value(output))
                applyOutputName(output, names.value(output));
            if (m_deadTimes.value(output) != times.value(output))
                applyDeadTime(output, times.value(output));
        }
    }
    if (edited && !keepEdits) m_undoStack->endMacro();
    Q_EMIT deviceStateChanged();
    notifyChangedCount();
}

void CamDocument::mergeDeadTime(int output, qint32 deadTime, bool fromDevice, bool keepEdits) {
    const bool edited = m_carriedDeadTimes.contains(output) ||
                        m_deadTimes.value(output) != m_deviceDeadTimes.value(output);
    if (fromDevice || !keepEdits) m_carriedDeadTimes.remove(output);
    if (fromDevice) m_deviceDeadTimes.insert(output, deadTime);
    if (!(keepEdits && edited) && m_deadTimes.value(output) != deadTime)
        applyDeadTime(output, deadTime);
    Q_EMIT deviceStateChanged();
    notifyChangedCount();
}

int CamDocument::outputSettingsEditCount() const {
    int count = 0;
    for (int output = 1; output <= m_info.outputs; ++output) {
        count += int(m_names.outputs.value(output) != m_deviceOutputNames.value(output));
        count += int(m_deadTimes.value(output) != m_deviceDeadTimes.value(output));
    }
    return count;
}

void CamDocument::setDeviceProgram(const CamProgram& program) {
    m_device.insert(program.number, normalized(program));
    forgetUnknownTracks(program.number);
    // A program only read, never edited, is shown as the device has it.
    if (!m_edited.contains(program.number))
        m_edited.insert(program.number, m_device.value(program.number));
    Q_EMIT programChanged(program.number);
    Q_EMIT deviceStateChanged();
    notifyChangedCount();
}

void CamDocument::setMinimumPulse(int output, qint32 tenths) {
    MinimumPulses pulses = m_minimumPulses;
    if (tenths > 0)
        pulses.insert(output, tenths);
    else
        pulses.remove(output);
    setMinimumPulses(pulses);
}

void CamDocument::setMinimumPulses(const MinimumPulses& pulses) {
    if (pulses == m_minimumPulses) return;
    m_minimumPulses = pulses;
    Q_EMIT minimumPulsesChanged();
}

void CamDocument::setDeviceTrack(int program, const Track& track) {
    if (!m_device.contains(program)) return;
    Track clean = normalized(track);
    m_unknownTracks.remove(trackKey(program, clean.output));
    if (clean.cams.isEmpty()) {
        m_device[program].tracks.remove(clean.output);
    } else {
        m_device[program].tracks.insert(clean.output, clean);
    }
    Q_EMIT deviceStateChanged();
    notifyChangedCount();
}

void CamDocument::setDeviceProgramName(int program, const QString& name) {
    if (!m_device.contains(program)) return;
    m_device[program].name = name;
    Q_EMIT deviceStateChanged();
    notifyChangedCount();
}

void CamDocument::setDeviceDeadTime(int output, qint32 deadTime) {
    m_deviceDeadTimes.insert(output, deadTime);
    Q_EMIT deviceStateChanged();
    notifyChangedCount();
}

void CamDocument::setDeviceOutputName(int output, const QString& name) {
    m_deviceOutputNames.insert(output, name);
    Q_EMIT deviceStateChanged();
    notifyChangedCount();
}

void CamDocument::forgetDeviceTrack(int program, int output) {
    if (!m_device.contains(program)) return;
    m_unknownTracks.insert(trackKey(program, output));
    Q_EMIT programChanged(program);
    Q_EMIT deviceStateChanged();
    notifyChangedCount();
}

void CamDocument::forgetUnknownTracks(int program) {
    for (auto it = m_unknownTracks.begin(); it != m_unknownTracks.end();) {
        it = (int(*it >> 16) == program) ? m_unknownTracks.erase(it) : std::next(it);
    }
}

bool CamDocument::deviceTrackKnown(int program, int output) const {
    return m_device.contains(program) && !m_unknownTracks.contains(trackKey(program, output));
}

void CamDocument::forgetDeviceCopies(CarryOver carry) {
    const bool all = carry == CarryOver::Everything;
    QMap<int, CamProgram> kept;
    QSet<quint32> tracks;
    QSet<int> programNames;
    for (auto it = m_edited.cbegin(); carry != CarryOver::Nothing && it != m_edited.cend(); ++it) {
        const int number = it.key();
        const CamProgram shown = program(number);
        const bool read = m_device.contains(number);
        CamProgram carried;
        carried.number = number;
        for (int output = 1; output <= m_info.outputs; ++output) {
            const Track mine = trackOf(shown, output);
            // Without the device's track, what the program holds is the
            // person's (typed, or from a project): an empty track is no change.
            const bool changed = deviceTrackKnown(number, output)
                                     ? mine.cams != trackOf(m_device.value(number), output).cams
                                     : !mine.cams.isEmpty();
            if (!changed && !(all && read)) continue;
            tracks.insert(trackKey(number, output));
            if (!mine.cams.isEmpty()) carried.tracks.insert(output, mine);
        }
        const bool nameChanged =
            read ? shown.name != m_device.value(number).name : !shown.name.isEmpty();
        if (nameChanged || (all && read)) {
            programNames.insert(number);
            carried.name = shown.name;
        }
        if (!carried.tracks.isEmpty() || !carried.name.isEmpty()) kept.insert(number, carried);
    }
    QSet<int> outputNames;
    QSet<int> deadTimes;
    for (int output = 1; carry != CarryOver::Nothing && output <= m_info.outputs; ++output) {
        const QString name = m_names.outputs.value(output);
        const qint32 deadTime = m_deadTimes.value(output);
        const bool known = m_outputSettingsKnown;
        if (known ? name != m_deviceOutputNames.value(output) || all : !name.isEmpty())
            outputNames.insert(output);
        // A dead time is known alone too: read or written with its output's
        // dead-time mode (table interface).
        const bool timeKnown = known || m_deviceDeadTimes.contains(output);
        if (timeKnown ? deadTime != m_deviceDeadTimes.value(output) || all : deadTime != 0)
            deadTimes.insert(output);
    }
    QList<int> programs = m_edited.keys() + m_device.keys();
    std::sort(programs.begin(), programs.end());
    programs.erase(std::unique(programs.begin(), programs.end()), programs.end());
    m_undoStack->clear();
    m_edited = kept;
    m_device.clear();
    m_unknownTracks.clear();
    QMap<int, QString> names;
    DeadTimes times;
    for (int output : outputNames) names.insert(output, m_names.outputs.value(output));
    for (int output : deadTimes) times.insert(output, m_deadTimes.value(output));
    m_names.outputs = names;
    m_deadTimes = times;
    m_deviceOutputNames.clear();
    m_deviceDeadTimes.clear();
    m_outputSettingsKnown = false;
    m_carriedTracks = tracks;
    m_carriedProgramNames = programNames;
    m_carriedOutputNames = outputNames;
    m_carriedDeadTimes = deadTimes;
    for (int program : programs) Q_EMIT programChanged(program);
    for (int output = 1; output <= m_info.outputs; ++output) {
        Q_EMIT outputNameChanged(output);
        Q_EMIT deadTimeChanged(output);
    }
    Q_EMIT deviceStateChanged();
    notifyChangedCount();
}

bool CamDocument::carriedTrack(int program, int output) const {
    return m_carriedTracks.contains(trackKey(program, output));
}

bool CamDocument::carryEdits(int program) const {
    if (m_carriedProgramNames.contains(program)) return true;
    return std::any_of(m_carriedTracks.cbegin(), m_carriedTracks.cend(),
                       [program](quint32 key) { return int(key >> 16) == program; });
}

std::optional<CamProgram> CamDocument::deviceProgram(int program) const {
    if (!m_device.contains(program)) return std::nullopt;
    CamProgram copy = m_device.value(program);
    copy.number = program;
    return copy;
}

std::optional<Track> CamDocument::deviceTrack(int program, int output) const {
    if (!deviceTrackKnown(program, output)) return std::nullopt;
    return trackOf(m_device.value(program), output);
}

std::optional<qint32> CamDocument::deviceDeadTime(int output) const {
    if (!m_outputSettingsKnown && !m_deviceDeadTimes.contains(output)) return std::nullopt;
    return m_deviceDeadTimes.value(output);
}

std::optional<QString> CamDocument::deviceOutputName(int output) const {
    if (!m_outputSettingsKnown && !m_deviceOutputNames.contains(output)) return std::nullopt;
    return m_deviceOutputNames.value(output);
}

ChangeState CamDocument::outputNameState(int output) const {
    const std::optional<QString> device = deviceOutputName(output);
    return compare(device.has_value(), device == outputName(output));
}

ChangeState CamDocument::deadTimeState(int output) const {
    const std::optional<qint32> device = deviceDeadTime(output);
    return compare(device.has_value(), device == deadTime(output));
}

ChangeState CamDocument::programState(int program) const {
    return compare(m_device.contains(program), this->program(program) == m_device.value(program));
}

ChangeState CamDocument::trackState(int program, int output) const {
    return compare(deviceTrackKnown(program, output),
                   track(program, output).cams == trackOf(m_device.value(program), output).cams);
}

ChangeState CamDocument::camState(int program, int output, int index) const {
    const QList<Cam> cams = track(program, output).cams;
    const bool onDevice = index >= 0 && index < cams.size() &&
                          trackOf(m_device.value(program), output).cams.contains(cams.at(index));
    return compare(deviceTrackKnown(program, output), onDevice);
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
            const bool known = deviceTrackKnown(number, output);
            TrackDifference difference{number, output, known,
                                       known ? trackOf(device, output) : Track{},
                                       trackOf(edited, output)};
            // A track whose state on the device is unknown (a write cut off)
            // differs until it is read or written again.
            if (!known && m_device.contains(number)) {
                result.append(difference);
            } else if (difference.deviceTrack != difference.editedTrack) {
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

quint64 CamDocument::newDragKey() {
    return ++m_lastDragKey;
}

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
        m_undoStack->push(new ReplaceTrackCommand(this, toProgram, before, copy,
                                                  tr("Copy output %1 to output %2 of program %3")
                                                      .arg(fromOutput)
                                                      .arg(toOutput)
                                                      .arg(toProgram)));
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

void CamDocument::replaceTracks(int program, const QMap<int, Track>& tracks, const QString& text) {
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
