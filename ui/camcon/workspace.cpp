#include "workspace.h"

#include "ui/camcon/cameditor/cam_document.h"

#include <algorithm>

namespace cambench {

namespace {

const User* findByNumber(const QList<User>& users, const QString& number) {
    for (const User& user : users) {
        if (!number.isEmpty() && user.number == number) return &user;
    }
    return nullptr;
}

const User* findByName(const QList<User>& users, const QString& name) {
    for (const User& user : users) {
        if (user.name == name) return &user;
    }
    return nullptr;
}

}  // namespace

template <class Self, class Visit>
void Workspace::forEachSection(Self& self, Visit visit) {
    visit(self.m_settings, ProjectPart::Settings, &Workspace::settingsChanged);
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
    m_users.clear();
    m_deviceUsers.clear();
    m_usersKnown = false;
    m_copiesFrom.reset();
    m_fingerprintKnown = false;
    m_carriedFrom.reset();
    clearOtherDeviceNote();
    setInfo(info, false);
    Q_EMIT usersChanged();
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

// --- users

QString Workspace::deviceNumberFor(const User& user) const {
    // A project may hold users without their numbers: the device's user
    // of the same name is the one meant.
    if (const User* device = findByNumber(m_deviceUsers, user.number)) return device->number;
    if (user.number.isEmpty()) {
        if (const User* device = findByName(m_deviceUsers, user.name)) return device->number;
    }
    return {};
}

void Workspace::mergeUsers(const QList<User>& users, ValueSource source, bool keepEdits) {
    if (source == ValueSource::File) {
        mergeUsersFromFile(users, keepEdits);
        return;
    }
    QList<EditedUser> kept;  // edited users that keep their edit
    QStringList deleted;
    if (keepEdits) {
        for (int i = 0; i < m_users.size(); ++i) {
            if (userChanged(i)) kept << m_users.at(i);
        }
        deleted = deletedUserNumbers();
    }
    m_deviceUsers = users;
    m_usersKnown = true;
    // The device's list, with the user's edits in place of their users.
    QList<EditedUser> result;
    for (const User& user : users) {
        if (deleted.contains(user.number)) continue;
        const auto mine = std::find_if(kept.begin(), kept.end(), [&](const EditedUser& e) {
            return e.deviceNumber == user.number;
        });
        if (mine != kept.end()) {
            result << *mine;
            kept.erase(mine);
        } else {
            result << EditedUser{user, user.number};
        }
    }
    // Edited users the device does not have (new ones, or gone from it).
    for (EditedUser& edited : kept) {
        if (!findByNumber(m_deviceUsers, edited.deviceNumber)) edited.deviceNumber.clear();
        result << edited;
    }
    m_users = result;
    Q_EMIT usersChanged();
    notifyChanged();
}

void Workspace::mergeUsersFromFile(const QList<User>& users, bool keepEdits) {
    // A project names the users it wants; users it does not name are left
    // as they are (as the CLI's write of a project leaves them).
    for (User user : users) {
        if (user.number.isEmpty()) {
            // Saved without numbers: the device's user of the same name is meant.
            if (const User* device = findByName(m_deviceUsers, user.name))
                user.number = device->number;
        }
        const QString deviceNumber = deviceNumberFor(user);
        const auto same = std::find_if(m_users.begin(), m_users.end(), [&](const EditedUser& e) {
            return deviceNumber.isEmpty() ? e.deviceNumber.isEmpty() && e.user.name == user.name
                                          : e.deviceNumber == deviceNumber;
        });
        if (same == m_users.end()) {
            m_users << EditedUser{user, deviceNumber};
        } else if (!(keepEdits && userChanged(int(same - m_users.begin())))) {
            same->user = user;
        }
    }
    Q_EMIT usersChanged();
    notifyChanged();
}

void Workspace::setUser(int index, const User& user) {
    if (index < 0 || index >= m_users.size() || m_users[index].user == user) return;
    m_users[index].user = user;
    Q_EMIT usersChanged();
    notifyChanged();
}

int Workspace::addUser(const User& user) {
    m_users.append({user, QString()});
    Q_EMIT usersChanged();
    notifyChanged();
    return int(m_users.size()) - 1;
}

void Workspace::removeUser(int index) {
    if (index < 0 || index >= m_users.size()) return;
    m_users.removeAt(index);
    Q_EMIT usersChanged();
    notifyChanged();
}

const User* Workspace::deviceUser(const QString& number) const {
    return findByNumber(m_deviceUsers, number);
}

bool Workspace::userChanged(int index) const {
    const EditedUser& edited = m_users.at(index);
    if (edited.deviceNumber.isEmpty()) return true;
    const User* device = findByNumber(m_deviceUsers, edited.deviceNumber);
    return !device || !(*device == edited.user);
}

QStringList Workspace::deletedUserNumbers() const {
    QStringList numbers;
    for (const User& device : m_deviceUsers) {
        const bool kept = std::any_of(m_users.cbegin(), m_users.cend(), [&](const EditedUser& e) {
            return e.deviceNumber == device.number;
        });
        if (!kept) numbers << device.number;
    }
    return numbers;
}

int Workspace::userEditCount() const {
    int count = int(deletedUserNumbers().size());
    for (int i = 0; i < m_users.size(); ++i) count += userChanged(i) ? 1 : 0;
    return count;
}

void Workspace::setDeviceUser(int index, const QString& deviceNumber,
                              const std::optional<User>& actual) {
    m_deviceUsers.erase(
        std::remove_if(
            m_deviceUsers.begin(), m_deviceUsers.end(),
            [&](const User& u) { return !deviceNumber.isEmpty() && u.number == deviceNumber; }),
        m_deviceUsers.end());
    if (actual) m_deviceUsers.append(*actual);
    if (index >= 0 && index < m_users.size())
        m_users[index].deviceNumber = actual ? actual->number : QString();
    Q_EMIT usersChanged();
    notifyChanged();
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
    int count = m_cams->changedCount() + userEditCount();
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
    forgetDeviceUsers(carry);
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
    if (part == ProjectPart::Users) forgetDeviceUsers(CarryOver::Changes);
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

void Workspace::forgetDeviceUsers(CarryOver carry) {
    QList<EditedUser> kept;
    for (int i = 0; i < m_users.size() && carry != CarryOver::Nothing; ++i) {
        // A user's place on the old device means nothing on this one: a
        // carried user is added to it.
        if (carry == CarryOver::Everything || userChanged(i))
            kept << EditedUser{m_users.at(i).user, QString()};
    }
    m_users = kept;
    m_deviceUsers.clear();
    m_usersKnown = false;
    m_readAt.parts.remove(ProjectPart::Users);
    Q_EMIT usersChanged();
    notifyChanged();
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
