#include "model/camcon/device_workspace.h"

#include <algorithm>

namespace cambench {

template <class Self, class Visit>
void DeviceWorkspace::forEachSection(Self& self, Visit visit) {
    visit(self.m_settings, ProjectPart::Settings, &DeviceWorkspace::settingsChanged);
    visit(self.m_users, ProjectPart::Users, &DeviceWorkspace::usersChanged);
    visit(self.m_plc, ProjectPart::PlcNetworks, &DeviceWorkspace::plcChanged);
    visit(self.m_deadTimeModes, ProjectPart::DeadTimeModes, &DeviceWorkspace::deadTimeModesChanged);
    visit(self.m_analogueCams, ProjectPart::AnalogueCams, &DeviceWorkspace::tableSectionsChanged);
    visit(self.m_programmingProgram, ProjectPart::ProgrammingProgram,
          &DeviceWorkspace::tableSectionsChanged);
    visit(self.m_eepromLock, ProjectPart::EepromLock, &DeviceWorkspace::tableSectionsChanged);
}

DeviceWorkspace::DeviceWorkspace(QObject* parent) : QObject(parent) {
    forEachSection(*this, [this](auto& section, ProjectPart, auto signal) {
        section.onChange = [this, signal] {
            Q_EMIT(this->*signal)();
            notifyChanged();
        };
    });
    // The editor draws and checks cams on the axis the settings describe:
    // a linear axis has no wrapping cams.
    connect(this, &DeviceWorkspace::settingsChanged, this, [this] {
        const bool rotary = isRotaryAxis(m_settings.shown());
        if (m_camSection && m_camSection->isRotary() != rotary)
            m_camSection->setLimits(m_info, rotary);
    });
}

DeviceWorkspace::~DeviceWorkspace() = default;

void DeviceWorkspace::attachCams(CamSection* cams) {
    m_camSection = cams;
    m_camSection->setLimits(m_info, isRotaryAxis(m_settings.shown()));
    notifyChanged();
}

void DeviceWorkspace::setInfo(const DeviceInfo& info, bool fromDevice) {
    m_info = info;
    m_infoFromDevice = fromDevice;
    if (m_camSection) m_camSection->setLimits(info, isRotaryAxis(m_settings.shown()));
    Q_EMIT infoChanged();
}

void DeviceWorkspace::setProjectPath(const QString& path) {
    if (m_projectPath == path) return;
    m_projectPath = path;
    Q_EMIT projectPathChanged();
}

void DeviceWorkspace::clear(const DeviceInfo& info) {
    if (m_camSection) m_camSection->clear();
    forEachSection(*this, [](auto& section, ProjectPart, auto) { section.clear(); });
    m_readAt = {};
    m_copiesFrom.reset();
    m_fingerprintKnown = false;
    m_carriedFrom.reset();
    clearOtherDeviceNote();
    setInfo(info, false);
    Q_EMIT readTimesChanged();
    notifyChanged();
}

// --- read times

void DeviceWorkspace::setReadTime(ProjectPart part, const QDateTime& utc) {
    m_readAt.parts.insert(part, utc);
    Q_EMIT readTimesChanged();
}

void DeviceWorkspace::setProgramReadTime(int program, const QDateTime& utc) {
    m_readAt.programs.insert(program, utc);
    Q_EMIT readTimesChanged();
}

QDateTime DeviceWorkspace::lastReadTime() const {
    QDateTime last;
    for (const QDateTime& time : m_readAt.parts) last = std::max(last, time);
    for (const QDateTime& time : m_readAt.programs) last = std::max(last, time);
    return last;
}

// --- output names and dead times

bool DeviceWorkspace::outputSettingsKnown() const {
    return m_camSection && m_camSection->outputSettingsKnown();
}

qint32 DeviceWorkspace::deviceDeadTime(int output) const {
    return m_camSection ? m_camSection->deviceDeadTime(output).value_or(0) : 0;
}

QString DeviceWorkspace::deviceOutputName(int output) const {
    return m_camSection ? m_camSection->deviceOutputName(output).value_or(QString()) : QString();
}

void DeviceWorkspace::mergeOutputSettings(const QMap<int, QString>& names,
                                          const DeadTimes& deadTimes, ValueSource source,
                                          bool keepEdits) {
    if (!m_camSection) return;
    if (source == ValueSource::Device) {
        m_camSection->mergeOutputSettings(names, deadTimes, true, keepEdits);
        return;
    }
    // A file leaves the outputs it does not name as they are.
    QMap<int, QString> allNames = m_camSection->names().outputs;
    DeadTimes allDeadTimes = m_camSection->deadTimes();
    for (auto it = names.cbegin(); it != names.cend(); ++it) allNames.insert(it.key(), it.value());
    for (auto it = deadTimes.cbegin(); it != deadTimes.cend(); ++it)
        allDeadTimes.insert(it.key(), it.value());
    m_camSection->mergeOutputSettings(allNames, allDeadTimes, false, keepEdits);
}

int DeviceWorkspace::outputSettingsEditCount() const {
    return m_camSection ? m_camSection->outputSettingsEditCount() : 0;
}

// --- PLC

QMap<int, PlcNetwork> DeviceWorkspace::plcByKey(const QList<PlcNetwork>& networks) {
    QMap<int, PlcNetwork> byKey;
    for (const PlcNetwork& network : networks)
        byKey.insert(plcKey(network.area, network.number), network);
    return byKey;
}

PlcNetwork DeviceWorkspace::plcNetwork(int area, int number) const {
    PlcNetwork empty;
    empty.area = area;
    empty.number = number;
    return m_plc.value(plcKey(area, number)).value_or(empty);
}

// --- totals

int DeviceWorkspace::changedCount() const {
    int count = m_camSection ? m_camSection->changedCount() : 0;
    forEachSection(*this, [&count](const auto& section, ProjectPart, auto) {
        count += section.changedCount();
    });
    return count;
}

namespace {

// What the dead-time mode copies hold of a mode: all but word 0.
OutputDeadTime withoutWordZero(OutputDeadTime deadTime) {
    deadTime.normal = 0;
    return deadTime;
}

}  // namespace

std::optional<OutputDeadTime> DeviceWorkspace::deadTimeMode(int output) const {
    std::optional<OutputDeadTime> mode = m_deadTimeModes.value(output);
    if (mode && m_camSection) mode->normal = m_camSection->deadTimes().value(output);
    return mode;
}

std::optional<OutputDeadTime> DeviceWorkspace::deviceDeadTimeMode(int output) const {
    std::optional<OutputDeadTime> mode = m_deadTimeModes.deviceValue(output);
    if (mode && m_camSection) mode->normal = m_camSection->deviceDeadTime(output).value_or(0);
    return mode;
}

DeadTimeModes DeviceWorkspace::shownDeadTimeModes() const {
    DeadTimeModes modes;
    for (const int output : m_deadTimeModes.shown().keys())
        modes.insert(output, *deadTimeMode(output));
    return modes;
}

DeadTimeModes DeviceWorkspace::deviceDeadTimeModes() const {
    DeadTimeModes modes;
    for (const int output : m_deadTimeModes.device().keys())
        modes.insert(output, *deviceDeadTimeMode(output));
    return modes;
}

bool DeviceWorkspace::deadTimeModeChanged(int output) const {
    return deadTimeMode(output) != deviceDeadTimeMode(output);
}

void DeviceWorkspace::editDeadTimeMode(int output, const OutputDeadTime& deadTime) {
    if (m_camSection) m_camSection->setDeadTime(output, deadTime.normal);
    m_deadTimeModes.edit(output, withoutWordZero(deadTime));
}

void DeviceWorkspace::setDeviceDeadTimeMode(int output, const OutputDeadTime& deadTime) {
    if (m_camSection) m_camSection->setDeviceDeadTime(output, deadTime.normal);
    m_deadTimeModes.setDevice(output, withoutWordZero(deadTime));
}

void DeviceWorkspace::mergeDeadTimeModes(const DeadTimeModes& arriving, ValueSource source,
                                         bool keepEdits) {
    DeadTimeModes modes;
    for (auto it = arriving.cbegin(); it != arriving.cend(); ++it)
        modes.insert(it.key(), withoutWordZero(*it));
    const bool fromDevice = source == ValueSource::Device;
    if (fromDevice) {
        for (const int output : m_deadTimeModes.changedKeys()) {
            if (!modes.contains(output)) m_deadTimeModes.dropEdit(output);
        }
    } else {
        const DeadTimeModes& device = m_deadTimeModes.device();
        for (const int output : arriving.keys()) {
            if (!device.isEmpty() && !device.contains(output)) modes.remove(output);
        }
    }
    // Word 0 first: the modes' signal then shows the whole mode.
    if (m_camSection) {
        for (const int output : modes.keys())
            m_camSection->mergeDeadTime(output, arriving.value(output).normal, fromDevice,
                                        keepEdits);
    }
    if (fromDevice)
        m_deadTimeModes.mergeWhole(modes, keepEdits);
    else
        m_deadTimeModes.merge(modes, source, keepEdits);
}

// --- which device the copies are from

void DeviceWorkspace::setCopiesFrom(const DeviceInfo& identity) {
    m_copiesFrom = identity;
    m_fingerprintKnown = true;
}

bool DeviceWorkspace::copiesAreFrom(const DeviceInfo& now) const {
    return !m_copiesFrom || sameDevice(*m_copiesFrom, now, m_fingerprintKnown);
}

void DeviceWorkspace::forgetDeviceCopies(const QString& note, CarryOver carry) {
    const std::optional<DeviceInfo> from = m_copiesFrom;
    if (m_camSection) m_camSection->forgetDeviceCopies(carry);
    forEachSection(*this,
                   [carry](auto& section, ProjectPart, auto) { section.forgetDevice(carry); });
    m_readAt = {};
    m_copiesFrom.reset();
    m_fingerprintKnown = false;
    m_carriedFrom.reset();
    if (from && carry != CarryOver::Nothing) m_carriedFrom = CarriedFrom{*from, carry};
    m_otherDeviceNote = note;
    Q_EMIT readTimesChanged();
    Q_EMIT otherDeviceNoteChanged();
    notifyChanged();
}

void DeviceWorkspace::forgetDeviceSection(ProjectPart part) {
    forEachSection(*this, [part](auto& section, ProjectPart its, auto) {
        if (its == part) section.forgetDevice(CarryOver::Changes);
    });
    m_readAt.parts.remove(part);
    Q_EMIT readTimesChanged();
}

void DeviceWorkspace::forgetDeviceTableSections() {
    for (ProjectPart part : {ProjectPart::DeadTimeModes, ProjectPart::AnalogueCams,
                             ProjectPart::ProgrammingProgram, ProjectPart::EepromLock})
        forgetDeviceSection(part);
}

bool DeviceWorkspace::awaitsCarried(ProjectPart part) const {
    return m_carriedFrom && !m_readAt.parts.contains(part);
}

bool DeviceWorkspace::awaitsCarriedProgram(int program) const {
    return m_carriedFrom && !m_readAt.programs.contains(program);
}

void DeviceWorkspace::clearOtherDeviceNote() {
    if (m_otherDeviceNote.isEmpty()) return;
    m_otherDeviceNote.clear();
    Q_EMIT otherDeviceNoteChanged();
}

void DeviceWorkspace::notifyChanged() {
    const int count = changedCount();
    if (count == m_lastCount) return;
    m_lastCount = count;
    Q_EMIT changedCountChanged(count);
}

}  // namespace cambench
