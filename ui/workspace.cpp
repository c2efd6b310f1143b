#include "workspace.h"

#include "ui/cameditor/cam_document.h"

#include <algorithm>

namespace cambench {

namespace {

const User* findByNumber(const QList<User>& users, const QString& number) {
    for (const User& user : users) {
        if (user.number == number) return &user;
    }
    return nullptr;
}

}  // namespace

Workspace::Workspace(QObject* parent) : QObject(parent), m_cams(new CamDocument(this)) {
    m_cams->setLimits(m_info, true);
    connect(m_cams, &CamDocument::changedCountChanged, this, &Workspace::notifyChanged);
}

Workspace::~Workspace() = default;

void Workspace::setInfo(const DeviceInfo& info, bool fromDevice) {
    m_info = info;
    m_infoFromDevice = fromDevice;
    m_cams->setLimits(info, true);
    Q_EMIT infoChanged();
}

void Workspace::setProjectPath(const QString& path) {
    if (m_projectPath == path) return;
    m_projectPath = path;
    Q_EMIT projectPathChanged();
}

// --- output names and dead times

void Workspace::loadOutputSettingsFromDevice(const QMap<int, QString>& names,
                                             const DeadTimes& deadTimes) {
    m_deviceOutputNames = names;
    m_deviceDeadTimes = deadTimes;
    m_outputSettingsKnown = true;
    m_cams->loadOutputSettingsFromDevice(names, deadTimes);
}

void Workspace::markOutputSettingsWritten(const QList<int>& deadTimes, const QList<int>& names) {
    for (int output : deadTimes) m_deviceDeadTimes.insert(output, m_cams->deadTime(output));
    for (int output : names) m_deviceOutputNames.insert(output, m_cams->outputName(output));
    // The document only knows "all written"; hand it the new device copy and
    // put back the edits that did not reach the device.
    const DeadTimes editedDeadTimes = m_cams->deadTimes();
    const QMap<int, QString> editedNames = m_cams->names().outputs;
    m_cams->loadOutputSettingsFromDevice(m_deviceOutputNames, m_deviceDeadTimes);
    for (int output = 1; output <= m_info.outputs; ++output) {
        if (editedDeadTimes.value(output) != m_deviceDeadTimes.value(output))
            m_cams->applyDeadTime(output, editedDeadTimes.value(output));
        if (editedNames.value(output) != m_deviceOutputNames.value(output))
            m_cams->applyOutputName(output, editedNames.value(output));
    }
}

// --- settings

void Workspace::loadSettingsFromDevice(const SystemSettings& settings) {
    m_deviceSettings = settings;
    m_settings = settings;
    m_settingsKnown = true;
    Q_EMIT settingsChanged();
    notifyChanged();
}

void Workspace::loadSettingsOffline(const SystemSettings& settings) {
    m_settings = settings;
    Q_EMIT settingsChanged();
    notifyChanged();
}

void Workspace::setSetting(const QString& key, const QVariant& value) {
    if (m_settings.value(key) == value) return;
    m_settings.insert(key, value);
    Q_EMIT settingsChanged();
    notifyChanged();
}

void Workspace::markSettingsWritten(const QStringList& keys) {
    for (const QString& key : keys) m_deviceSettings.insert(key, m_settings.value(key));
    Q_EMIT settingsChanged();
    notifyChanged();
}

QStringList Workspace::changedSettings() const {
    QStringList keys;
    for (auto it = m_settings.cbegin(); it != m_settings.cend(); ++it) {
        if (!m_deviceSettings.contains(it.key()) || m_deviceSettings.value(it.key()) != it.value())
            keys << it.key();
    }
    return keys;
}

// --- users

void Workspace::loadUsersFromDevice(const QList<User>& users) {
    m_deviceUsers = users;
    m_users.clear();
    for (const User& user : users) m_users.append({user, user.number});
    Q_EMIT usersChanged();
    notifyChanged();
}

void Workspace::loadUsersOffline(const QList<User>& users) {
    m_users.clear();
    for (const User& user : users) {
        m_users.append({user, findByNumber(m_deviceUsers, user.number) ? user.number : QString()});
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

void Workspace::markUserWritten(int index) {
    EditedUser& edited = m_users[index];
    for (int i = 0; i < m_deviceUsers.size(); ++i) {
        if (!edited.deviceNumber.isEmpty() && m_deviceUsers[i].number == edited.deviceNumber) {
            m_deviceUsers[i] = edited.user;
            edited.deviceNumber = edited.user.number;
            Q_EMIT usersChanged();
            notifyChanged();
            return;
        }
    }
    m_deviceUsers.append(edited.user);
    edited.deviceNumber = edited.user.number;
    Q_EMIT usersChanged();
    notifyChanged();
}

void Workspace::markUserDeleted(const QString& number) {
    m_deviceUsers.erase(std::remove_if(m_deviceUsers.begin(), m_deviceUsers.end(),
                                       [&](const User& u) { return u.number == number; }),
                        m_deviceUsers.end());
    Q_EMIT usersChanged();
    notifyChanged();
}

// --- PLC

PlcNetwork Workspace::plcNetwork(int area, int number) const {
    PlcNetwork empty;
    empty.area = area;
    empty.number = number;
    return m_plc.value(plcKey(area, number), empty);
}

void Workspace::loadPlcFromDevice(const PlcNetwork& network) {
    const int key = plcKey(network.area, network.number);
    m_devicePlc.insert(key, network);
    m_plc.insert(key, network);
    Q_EMIT plcChanged();
    notifyChanged();
}

void Workspace::setPlcNetwork(const PlcNetwork& network) {
    const int key = plcKey(network.area, network.number);
    if (m_plc.contains(key) && m_plc.value(key) == network) return;
    m_plc.insert(key, network);
    Q_EMIT plcChanged();
    notifyChanged();
}

bool Workspace::isPlcNetworkChanged(int key) const {
    return !m_devicePlc.contains(key) || !(m_devicePlc.value(key) == m_plc.value(key));
}

QList<int> Workspace::changedPlcNetworks() const {
    QList<int> keys;
    for (auto it = m_plc.cbegin(); it != m_plc.cend(); ++it) {
        if (isPlcNetworkChanged(it.key())) keys << it.key();
    }
    return keys;
}

void Workspace::markPlcWritten(int key) {
    m_devicePlc.insert(key, m_plc.value(key));
    Q_EMIT plcChanged();
    notifyChanged();
}

// --- totals

int Workspace::changedCount() const {
    int users = int(deletedUserNumbers().size());
    for (int i = 0; i < m_users.size(); ++i) users += userChanged(i) ? 1 : 0;
    return m_cams->changedCount() + int(changedSettings().size()) + users +
           int(changedPlcNetworks().size());
}

void Workspace::notifyChanged() {
    const int count = changedCount();
    if (count == m_lastCount) return;
    m_lastCount = count;
    Q_EMIT changedCountChanged(count);
}

}  // namespace cambench
