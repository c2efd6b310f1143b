#include "table_section_copies.h"

#include "model/camcon/project_file.h"

namespace cambench {

namespace {

// One rule for every section: an edit that equals the device's value is none.
template <class T>
void setEdit(std::optional<T>& edit, const std::optional<T>& device, const T& wanted) {
    if (device && *device == wanted)
        edit.reset();
    else
        edit = wanted;
}

template <class T>
void setDevice(std::optional<T>& device, std::optional<T>& edit, const T& value) {
    device = value;
    if (edit && *edit == value) edit.reset();
}

// A project's value of one section: the device's copy or an edit.
template <class T>
void takeIncoming(const std::optional<T>& incoming, std::optional<T>& device,
                  std::optional<T>& edit, bool fromDevice) {
    if (!incoming) return;
    if (fromDevice)
        setDevice(device, edit, *incoming);
    else
        setEdit(edit, device, *incoming);
}

}  // namespace

std::optional<AnalogueCamTrack> TableSectionCopies::analogueCams(int output) const {
    if (m_analogueEdits.contains(output)) return m_analogueEdits.value(output);
    return deviceAnalogueCams(output);
}

std::optional<AnalogueCamTrack> TableSectionCopies::deviceAnalogueCams(int output) const {
    if (!m_deviceAnalogue.contains(output)) return std::nullopt;
    return m_deviceAnalogue.value(output);
}

void TableSectionCopies::putAnalogueEdit(const AnalogueCamTrack& track) {
    const std::optional<AnalogueCamTrack> device = deviceAnalogueCams(track.output);
    if (device && *device == track)
        m_analogueEdits.remove(track.output);
    else
        m_analogueEdits.insert(track.output, track);
}

void TableSectionCopies::putDeviceAnalogue(const AnalogueCamTrack& track) {
    m_deviceAnalogue.insert(track.output, track);
    if (m_analogueEdits.value(track.output) == track) m_analogueEdits.remove(track.output);
}

void TableSectionCopies::editAnalogueCams(const AnalogueCamTrack& track) {
    putAnalogueEdit(track);
    Q_EMIT changed();
}

void TableSectionCopies::setDeviceAnalogueCams(const AnalogueCamTrack& track) {
    putDeviceAnalogue(track);
    Q_EMIT changed();
}

QList<AnalogueCamTrack> TableSectionCopies::shownAnalogueCams() const {
    QMap<int, AnalogueCamTrack> shown = m_deviceAnalogue;
    for (auto it = m_analogueEdits.cbegin(); it != m_analogueEdits.cend(); ++it)
        shown.insert(it.key(), *it);
    return shown.values();
}

std::optional<ProgrammingProgram> TableSectionCopies::programmingProgram() const {
    return m_programmingEdit ? m_programmingEdit : m_deviceProgramming;
}

void TableSectionCopies::editProgrammingProgram(const ProgrammingProgram& programming) {
    setEdit(m_programmingEdit, m_deviceProgramming, programming);
    Q_EMIT changed();
}

void TableSectionCopies::setDeviceProgrammingProgram(const ProgrammingProgram& programming) {
    setDevice(m_deviceProgramming, m_programmingEdit, programming);
    Q_EMIT changed();
}

std::optional<bool> TableSectionCopies::eepromLock() const {
    return m_lockEdit ? m_lockEdit : m_deviceLock;
}

void TableSectionCopies::editEepromLock(bool locked) {
    setEdit(m_lockEdit, m_deviceLock, locked);
    Q_EMIT changed();
}

void TableSectionCopies::setDeviceEepromLock(bool locked) {
    setDevice(m_deviceLock, m_lockEdit, locked);
    Q_EMIT changed();
}

int TableSectionCopies::changedCount() const {
    return int(m_analogueEdits.size()) + (m_programmingEdit ? 1 : 0) + (m_lockEdit ? 1 : 0);
}

void TableSectionCopies::take(const Project& project, bool fromDevice) {
    for (const AnalogueCamTrack& track : project.analogueCams) {
        if (fromDevice)
            putDeviceAnalogue(track);
        else
            putAnalogueEdit(track);
    }
    takeIncoming(project.programmingProgram, m_deviceProgramming, m_programmingEdit, fromDevice);
    takeIncoming(project.eepromLock, m_deviceLock, m_lockEdit, fromDevice);
    Q_EMIT changed();
}

void TableSectionCopies::forgetDeviceCopies(CarryOver carry) {
    // What was shown from the old device is no edit: it goes with it,
    // unless the person wants it copied to the new device.
    if (carry == CarryOver::Nothing) {
        m_analogueEdits.clear();
        m_programmingEdit.reset();
        m_lockEdit.reset();
    } else if (carry == CarryOver::Everything) {
        for (const AnalogueCamTrack& track : shownAnalogueCams())
            m_analogueEdits.insert(track.output, track);
        m_programmingEdit = programmingProgram();
        m_lockEdit = eepromLock();
    }
    m_deviceAnalogue.clear();
    m_deviceProgramming.reset();
    m_deviceLock.reset();
    Q_EMIT changed();
}

void TableSectionCopies::clear() {
    m_deviceAnalogue.clear();
    m_analogueEdits.clear();
    m_deviceProgramming.reset();
    m_programmingEdit.reset();
    m_deviceLock.reset();
    m_lockEdit.reset();
    Q_EMIT changed();
}

void TableSectionCopies::dropAnalogueEdit(int output) {
    m_analogueEdits.remove(output);
    Q_EMIT changed();
}

void TableSectionCopies::dropProgrammingEdit() {
    m_programmingEdit.reset();
    Q_EMIT changed();
}

}  // namespace cambench
