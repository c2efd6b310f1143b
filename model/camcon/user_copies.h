#pragma once

#include "model/camcon/carry_over.h"
#include "model/camcon/section_copies.h"
#include "model/camcon/user.h"

#include <QList>
#include <QString>
#include <QStringList>

#include <functional>
#include <optional>

namespace cambench {

// The device's users as the PC holds them, in the one shape of the other
// sections (SectionCopies), keyed by the number a user has on the device.
// A user not yet written has a provisional key ("new user:1"), an edit of nullopt
// deletes the device's user; a device value of nullopt says the user is
// known to be gone from it (after a write). What this adapter adds is the
// list the pages show: the order of the users and, for each, the number it
// has on the device. The merge and forget rules are SectionCopies'; here is
// only what a user's place on the device means for them (a user whose device
// number is gone is a new user again).
class UserCopies {
public:
    // A user as shown, and the number it has on the device (empty: not on it).
    struct EditedUser {
        User user;
        QString deviceNumber;
    };

    // Called after every change.
    std::function<void()> onChange;

    // --- The users as shown, index = row on the users page.
    int size() const { return int(m_order.size()); }
    EditedUser row(int index) const;
    QList<EditedUser> rows() const;
    // Whether the user `index` differs from the device's (a new user does).
    bool isChanged(int index) const;
    // The device's users that no shown user stands for: to be deleted.
    QStringList deletedNumbers() const;
    // New, edited and deleted users.
    int changedCount() const { return m_copies.changedCount(); }

    // --- The device's copy, in the order the device listed them.
    QList<User> device() const;
    std::optional<User> deviceUser(const QString& number) const;
    // Whether the device's list was read since the last forgetDevice().
    bool known() const { return m_copies.known(); }

    // Users that arrive. A device's are its whole list (SectionCopies::
    // mergeWhole; without keepEdits every edit goes). A project's name the
    // users it wants, matched by device number, else by name; users it
    // does not name stay as they are.
    void merge(const QList<User>& users, ValueSource source, bool keepEdits);
    void set(int index, const User& user);
    // Returns the new user's index.
    int add(const User& user);
    void remove(int index);
    // After a write: the device's user `deviceNumber` is now `actual` (or
    // gone, when nullopt); the user `index` (-1: a deletion) follows.
    void setDevice(int index, const QString& deviceNumber, const std::optional<User>& actual);
    // SectionCopies::forgetDevice; a carried user is added to the next device.
    void forgetDevice(CarryOver carry);
    void clear();

private:
    using Copies = SectionCopies<QString, std::optional<User>>;

    bool onDevice(const QString& key) const;
    bool shown(const QString& key) const;
    QString newKey();
    // Moves the edit under `from` to `to`, in the same row.
    void rekey(const QString& from, const QString& to);
    // Edits of users the device no longer has: a deletion is moot, an
    // edited user is a new one; rows no longer shown go.
    void detachFromDevice();
    void notify() const;

    Copies m_copies;
    QStringList m_order;        // the keys of the users shown, in their order
    QStringList m_deviceOrder;  // the device's numbers, in its order
    int m_lastNew = 0;
};

}  // namespace cambench
