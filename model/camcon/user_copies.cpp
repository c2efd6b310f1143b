#include "user_copies.h"

namespace cambench {

namespace {

// A provisional key: longer than any number a user may have on the device
// (5 characters), so never one.
const QString kNewPrefix = QStringLiteral("new user:");

}  // namespace

UserCopies::EditedUser UserCopies::row(int index) const {
    const QString& key = m_order.at(index);
    return {m_copies.value(key)->value_or(User()), onDevice(key) ? key : QString()};
}

QList<UserCopies::EditedUser> UserCopies::rows() const {
    QList<EditedUser> all;
    for (int i = 0; i < size(); ++i) all << row(i);
    return all;
}

bool UserCopies::isChanged(int index) const {
    return m_copies.isChanged(m_order.at(index));
}

QStringList UserCopies::deletedNumbers() const {
    QStringList numbers;
    for (const QString& number : m_deviceOrder) {
        if (onDevice(number) && !shown(number)) numbers << number;
    }
    return numbers;
}

QList<User> UserCopies::device() const {
    QList<User> users;
    for (const QString& number : m_deviceOrder) {
        if (const std::optional<User> user = deviceUser(number)) users << *user;
    }
    return users;
}

std::optional<User> UserCopies::deviceUser(const QString& number) const {
    if (number.isEmpty()) return std::nullopt;
    if (const auto user = m_copies.deviceValue(number)) return *user;
    return std::nullopt;
}

void UserCopies::merge(const QList<User>& users, ValueSource source, bool keepEdits) {
    if (source == ValueSource::Device) {
        Copies::Map byNumber;
        for (const User& user : users) byNumber.insert(user.number, user);
        // Without keepEdits every edit goes, also of users the device does
        // not name (new ones).
        for (const QString& key : m_copies.changedKeys()) {
            if (!keepEdits && !byNumber.contains(key)) m_copies.dropEdit(key);
        }
        m_copies.mergeWhole(byNumber, keepEdits);
        m_deviceOrder.clear();
        for (const User& user : users) {
            if (!m_deviceOrder.contains(user.number)) m_deviceOrder << user.number;
        }
        detachFromDevice();
        // The device's list, edited users in place of theirs, then the
        // users not on it.
        QStringList order;
        for (const QString& number : m_deviceOrder) {
            if (shown(number)) order << number;
        }
        for (const QString& key : m_order) {
            if (!onDevice(key)) order << key;
        }
        m_order = order;
        notify();
        return;
    }
    for (User user : users) {
        // Saved without numbers: the device's user of the same name is meant.
        if (user.number.isEmpty()) {
            for (const User& device : device()) {
                if (device.name == user.name) {
                    user.number = device.number;
                    break;
                }
            }
        }
        QString key = onDevice(user.number) ? user.number : QString();
        for (int i = 0; key.isEmpty() && i < size(); ++i) {
            const EditedUser shownUser = row(i);
            if (shownUser.deviceNumber.isEmpty() && shownUser.user.name == user.name)
                key = m_order.at(i);
        }
        if (!key.isEmpty() && m_order.contains(key)) {
            m_copies.merge({{key, user}}, ValueSource::File, keepEdits);
            continue;
        }
        if (key.isEmpty()) key = newKey();
        m_order << key;
        m_copies.edit(key, user);
    }
    notify();
}

void UserCopies::set(int index, const User& user) {
    if (index < 0 || index >= size() || row(index).user == user) return;
    m_copies.edit(m_order.at(index), user);
    notify();
}

int UserCopies::add(const User& user) {
    const QString key = newKey();
    m_order << key;
    m_copies.edit(key, user);
    notify();
    return size() - 1;
}

void UserCopies::remove(int index) {
    if (index < 0 || index >= size()) return;
    const QString key = m_order.takeAt(index);
    if (onDevice(key))
        m_copies.edit(key, std::nullopt);
    else
        m_copies.dropEdit(key);
    notify();
}

void UserCopies::setDevice(int index, const QString& deviceNumber,
                           const std::optional<User>& actual) {
    const bool isRow = index >= 0 && index < size();
    const QString key = isRow ? m_order.at(index) : QString();
    const User wanted = isRow ? row(index).user : User();
    if (!deviceNumber.isEmpty() && !(actual && actual->number == deviceNumber)) {
        m_copies.setDevice(deviceNumber, std::nullopt);
        m_deviceOrder.removeAll(deviceNumber);
    }
    if (actual) {
        m_copies.setDevice(actual->number, actual);
        m_deviceOrder.removeAll(actual->number);
        m_deviceOrder << actual->number;
    }
    // The user written is now the device's user of its number (none: a
    // user to be added again).
    const QString now = actual ? actual->number : newKey();
    if (isRow && now != key) {
        m_copies.dropEdit(key);
        m_order[index] = now;
        m_copies.edit(now, wanted);
    }
    notify();
}

void UserCopies::forgetDevice(CarryOver carry) {
    m_copies.forgetDevice(carry);
    m_deviceOrder.clear();
    detachFromDevice();
    notify();
}

void UserCopies::clear() {
    m_copies.clear();
    m_order.clear();
    m_deviceOrder.clear();
    notify();
}

bool UserCopies::onDevice(const QString& key) const {
    const auto device = m_copies.deviceValue(key);
    return device && device->has_value();
}

bool UserCopies::shown(const QString& key) const {
    const auto user = m_copies.value(key);
    return user && user->has_value();
}

QString UserCopies::newKey() {
    return kNewPrefix + QString::number(++m_lastNew);
}

void UserCopies::rekey(const QString& from, const QString& to) {
    const std::optional<User> user = *m_copies.value(from);
    m_copies.dropEdit(from);
    m_copies.edit(to, user);
    const qsizetype index = m_order.indexOf(from);
    if (index >= 0)
        m_order[index] = to;
    else
        m_order << to;
}

void UserCopies::detachFromDevice() {
    for (const QString& key : m_copies.changedKeys()) {
        if (onDevice(key)) continue;
        // A user's place on a device it is not on means nothing: a
        // deletion there is moot, an edited user is added to it.
        if (!shown(key))
            m_copies.dropEdit(key);
        else if (!key.startsWith(kNewPrefix))
            rekey(key, newKey());
    }
    m_order.removeIf([this](const QString& key) { return !shown(key); });
}

void UserCopies::notify() const {
    if (onChange) onChange();
}

}  // namespace cambench
