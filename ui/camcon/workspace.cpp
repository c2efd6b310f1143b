#include "workspace.h"

#include "ui/camcon/cameditor/cam_document.h"

#include <algorithm>

namespace cambench {

template <class Self, class Visit>
void Workspace::forEachSection(Self& self, Visit visit) {
    visit(self.m_settings, ProjectPart::Settings, &Workspace::settingsChanged);
    visit(self.m_users, ProjectPart::Users, &Workspace::usersChanged);
    visit(self.m_plc, ProjectPart::PlcNetworks, &Workspace::plcChanged);
    visit(self.m_deadTimeModes, ProjectPart::DeadTimeModes, &Workspace::deadTimeModesChanged);
    visit(self.m_analogueCams, ProjectPart::AnalogueCams, &Workspace::tableSectionsChanged);
    visit(self.m_programmingProgram, ProjectPart::ProgrammingProgram,
          &Workspace::tableSectionsChanged);
    visit(self.m_eepromLock, ProjectPart::EepromLock, &Workspace::tableSectionsChanged);
}

Workspace::Workspace(QObject* parent) : QObject(parent), m_cams(new CamDocument(this)) {
    m_cams->setLimits(m_info, true);
    connect(m_cams, &CamDocument::changedCountChanged, this, &Workspace::notifyChanged);
    forEachSection(*this, [this](auto& section, ProjectPart, auto signal) {
        section.onChange = [this, signal] {
            Q_EMIT(this->*signal)();
            notifyChanged();
        };
    });
    // The editor draws and checks cams on the axis the settings describe:
    // a linear axis has no wrapping cams.
    connect(this, &Workspace::settingsChanged, this, [this] {
        const bool rotary = isRotaryAxis(m_settings.shown());
        if (m_cams->isRotary() != rotary) m_cams->setLimits(m_info, rotary);
    });
}

Workspace::~Workspace() = default;

void Workspace::setInfo(const DeviceInfo& info, bool fromDevice) {
    m_info = info;
    m_infoFromDevice = fromDevice;
    m_cams->setLimits(info, isRotaryAxis(m_settings.shown()));
    Q_EMIT infoChanged();
}

void Workspace::setProjectPath(const QString& path) {
    if (m_projectPath == path) return;
    m_projectPath = path;
    Q_EMIT projectPathChanged();
}

void Workspace::clear(const DeviceInfo& info) {
    m_cams->clear();
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

void Workspace::setReadTime(ProjectPart part, const QDateTime& utc) {
    m_readAt.parts.insert(part, utc);
    Q_EMIT readTimesChanged();
}

void Workspace::setProgramReadTime(int program, const QDateTime& utc) {
    m_readAt.programs.insert(program, utc);
    Q_EMIT readTimesChanged();
}

QDateTime Workspace::lastReadTime() const {
    QDateTime last;
    for (const QDateTime& time : m_readAt.parts) last = std::max(last, time);
    for (const QDateTime& time : m_readAt.programs) last = std::max(last, time);
    return last;
}

// --- output names and dead times

bool Workspace::outputSettingsKnown() const {
    return m_cams->outputSettingsKnown();
}

qint32 Workspace::deviceDeadTime(int output) const {
    return m_cams->deviceDeadTime(output).value_or(0);
}

QString Workspace::deviceOutputName(int output) const {
    return m_cams->deviceOutputName(output).value_or(QString());
}

void Workspace::mergeOutputSettings(const QMap<int, QString>& names, const DeadTimes& deadTimes,
                                    ValueSource source, bool keepEdits) {
    if (source == ValueSource::Device) {
        m_cams->mergeOutputSettings(names, deadTimes, true, keepEdits);
        return;
    }
    // A file leaves the outputs it does not name as they are.
    QMap<int, QString> allNames = m_cams->names().outputs;
    DeadTimes allDeadTimes = m_cams->deadTimes();
    for (auto it = names.cbegin(); it != names.cend(); ++it) allNames.insert(it.key(), it.value());
    for (auto it = deadTimes.cbegin(); it != deadTimes.cend(); ++it)
        allDeadTimes.insert(it.key(), it.value());
    m_cams->mergeOutputSettings(allNames, allDeadTimes, false, keepEdits);
}

int Workspace::outputSettingsEditCount() const {
    return m_cams->outputSettingsEditCount();
}

// --- PLC

QMap<int, PlcNetwork> Workspace::plcByKey(const QList<PlcNetwork>& networks) {
    QMap<int, PlcNetwork> byKey;
    for (const PlcNetwork& network : networks)
        byKey.insert(plcKey(network.area, network.number), network);
    return byKey;
}

PlcNetwork Workspace::plcNetwork(int area, int number) const {
    PlcNetwork empty;
    empty.area = area;
    empty.number = number;
    return m_plc.value(plcKey(area, number)).value_or(empty);
}

// --- totals

int Workspace::changedCount() const {
    int count = m_cams->changedCount();
    forEachSection(*this, [&count](const auto& section, ProjectPart, auto) {
        count += section.changedCount();
    });
    return count;
}

void Workspace::mergeDeadTimeModes(const DeadTimeModes& modes, ValueSource source, bool keepEdits) {
    if (source == ValueSource::Device) {
        for (const int output : m_deadTimeModes.changedKeys()) {
            if (!modes.contains(output)) m_deadTimeModes.dropEdit(output);
        }
        m_deadTimeModes.mergeWhole(modes, keepEdits);
        return;
    }
    const DeadTimeModes& device = m_deadTimeModes.device();
    DeadTimeModes shown = modes;
    for (const int output : modes.keys()) {
        if (!device.isEmpty() && !device.contains(output)) shown.remove(output);
    }
    m_deadTimeModes.merge(shown, source, keepEdits);
}

// --- which device the copies are from

void Workspace::setCopiesFrom(const DeviceInfo& identity) {
    m_copiesFrom = identity;
    m_fingerprintKnown = true;
}

bool Workspace::copiesAreFrom(const DeviceInfo& now) const {
    return !m_copiesFrom || sameDevice(*m_copiesFrom, now, m_fingerprintKnown);
}

void Workspace::forgetDeviceCopies(const QString& note, CarryOver carry) {
    const std::optional<DeviceInfo> from = m_copiesFrom;
    m_cams->forgetDeviceCopies(carry);
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

void Workspace::forgetDeviceSection(ProjectPart part) {
    forEachSection(*this, [part](auto& section, ProjectPart its, auto) {
        if (its == part) section.forgetDevice(CarryOver::Changes);
    });
    m_readAt.parts.remove(part);
    Q_EMIT readTimesChanged();
}

void Workspace::forgetDeviceTableSections() {
    for (ProjectPart part : {ProjectPart::DeadTimeModes, ProjectPart::AnalogueCams,
                             ProjectPart::ProgrammingProgram, ProjectPart::EepromLock})
        forgetDeviceSection(part);
}

bool Workspace::awaitsCarried(ProjectPart part) const {
    return m_carriedFrom && !m_readAt.parts.contains(part);
}

bool Workspace::awaitsCarriedProgram(int program) const {
    return m_carriedFrom && !m_readAt.programs.contains(program);
}

void Workspace::clearOtherDeviceNote() {
    if (m_otherDeviceNote.isEmpty()) return;
    m_otherDeviceNote.clear();
    Q_EMIT otherDeviceNoteChanged();
}

void Workspace::notifyChanged() {
    const int count = changedCount();
    if (count == m_lastCount) return;
    m_lastCount = count;
    Q_EMIT changedCountChanged(count);
}

}  // namespace cambench
