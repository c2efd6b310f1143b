#include "ascii_camcon.h"

#include <QCoreApplication>
#include <QHash>

#include "ascii_support.h"
#include "model/walked_list.h"

namespace cambench::comm {

using namespace client;

namespace {

// A device holds far fewer users; a list that never ends is a broken
// device or a misread end marker (provisional, notes 4).
constexpr int kMaxUsers = 256;
constexpr int kAccessBytes = 32;
constexpr int kAccessOutputs = kAccessBytes * 8;

User userFrom(const Fields& fields) {
    User user;
    user.name = text(fields, "name");
    user.number = text(fields, "number");
    const QByteArray access = fields.bytes("access");
    user.outputAccess = QList<bool>(kAccessOutputs, false);
    for (int i = 0; i < kAccessOutputs && i / 8 < access.size(); ++i) {
        user.outputAccess[i] = (quint8(access.at(i / 8)) >> (i % 8)) & 1;
    }
    user.allOutputs = fields.num("all") != 0;
    user.rights = quint32(fields.num("rights"));
    return user;
}

// Walks of the user list before giving up: enough that, with one reply in
// ten lost, every neighbouring pair of a list of dozens of users has been
// seen with nothing skipped in one of them (issue 12, point 1).
constexpr int kMaxWalks = 8;

// Users are told apart by name and number (notes 4).
QString keyOf(const User& user) {
    return user.name + QChar(0x1f) + user.number;
}

// One walk from ?USER00 to the empty entry, to kMaxUsers entries, or to the
// first step that found no answer. A step that went out more than once (its
// reply lost, Standard framing) may have moved the device's cursor twice:
// an entry before the reply may be skipped, and as the reply may be the
// late one to the first sending, also one before the next step's reply.
Result<ListWalk> walkUsers(AsciiLink& link, QHash<QString, User>& users) {
    ListWalk walk;
    bool afterRepeat = false;
    for (int i = 0; i <= kMaxUsers; ++i) {
        const Result<Fields> reply =
            link.call('?', "USER", Fields{{"index", qint64(i == 0 ? 0 : 1)}});
        if (!reply) {
            if (i > 0 && reply.error().kind == ErrorKind::Communication) return walk;
            return inContext(
                QCoreApplication::translate("cambench::comm", "reading user entry %1 (?USER)")
                    .arg(i + 1),
                reply.error());
        }
        // ?USER00 only resets the cursor: sent twice, it is still at the start.
        const bool repeated = i > 0 && link.lastCallMayHaveActedTwice();
        const bool maySkip = repeated || afterRepeat;
        afterRepeat = repeated;
        if (reply->bytes("name").isEmpty() && reply->bytes("number").isEmpty()) {
            walk.reachedEnd = true;
            walk.endMaySkip = maySkip;
            return walk;
        }
        if (i == kMaxUsers) break;
        const User user = userFrom(*reply);
        users.insert(keyOf(user), user);
        walk.steps.append({keyOf(user), maySkip});
    }
    return Error::communication(
        QCoreApplication::translate(
            "cambench::comm",
            "reading the users: the device lists more than %1 entries and no end; "
            "check the device")
            .arg(kMaxUsers));
}

// "user "Operator"" (never the number: it is the user's password), or the
// start or end of the list.
QString placeName(const QString& key, bool isEnd, const QHash<QString, User>& users) {
    if (key.isEmpty()) {
        return isEnd ? QCoreApplication::translate("cambench::comm", "the end of the list")
                     : QCoreApplication::translate("cambench::comm", "the start of the list");
    }
    const User user = users.value(key);
    return QCoreApplication::translate("cambench::comm", "user \"%1\"").arg(user.name);
}

QString uncertainParts(const WalkedList& merged, const QHash<QString, User>& users) {
    // A few places are enough to see where the line is bad.
    constexpr qsizetype kShownPlaces = 3;
    QStringList parts;
    for (const auto& [before, after] : merged.uncertainGaps.mid(0, kShownPlaces)) {
        parts.append(QCoreApplication::translate("cambench::comm", "between %1 and %2")
                         .arg(placeName(before, false, users), placeName(after, true, users)));
    }
    if (merged.uncertainGaps.size() > kShownPlaces) {
        parts.append(QCoreApplication::translate("cambench::comm", "and %1 more places")
                         .arg(merged.uncertainGaps.size() - kShownPlaces));
    }
    return parts.join(QStringLiteral("; "));
}

QByteArray accessBytes(const User& user) {
    QByteArray bytes(kAccessBytes, '\0');
    for (int i = 0; i < kAccessOutputs && i < user.outputAccess.size(); ++i) {
        if (user.outputAccess.at(i)) bytes[i / 8] = char(quint8(bytes.at(i / 8)) | (1u << (i % 8)));
    }
    return bytes;
}

}  // namespace

Result<QList<User>> AsciiCamCon::readUsers() {
    // ?USER00 starts a walk, ?USER01 steps the device's cursor to the next
    // entry. Walks go on until, merged, they show every neighbouring pair of
    // the list and its end with nothing skipped, a bounded number of times;
    // a list still uncertain then is refused, naming the uncertain part.
    QHash<QString, User> users;
    QList<ListWalk> walks;
    WalkedList merged;
    for (int attempt = 1; attempt <= kMaxWalks; ++attempt) {
        Result<ListWalk> walk = walkUsers(m_link, users);
        if (!walk) return walk.error();
        walks.append(std::move(*walk));
        merged = mergeWalks(walks);
        if (merged.contradicted) {
            return Error::communication(
                QCoreApplication::translate(
                    "cambench::comm",
                    "reading the users: the list changed while it was read (near %1); "
                    "nothing is shown; read it again")
                    .arg(placeName(merged.contradictionAt, false, users)));
        }
        if (merged.complete) {
            QList<User> list;
            for (const QString& key : merged.keys) list.append(users.value(key));
            return list;
        }
    }
    return Error::communication(
        QCoreApplication::translate(
            "cambench::comm",
            "reading the users: after %1 walks through the list, %2 users were seen but one "
            "may still be missing %3; the list may be incomplete, so none is shown; check the "
            "cable and try again")
            .arg(kMaxWalks)
            .arg(merged.keys.size())
            .arg(uncertainParts(merged, users)));
}

Status AsciiCamCon::writeUser(const QString& oldNumber, const User& user) {
    Fields fields{{"all", qint64(user.allOutputs ? 1 : 0)}, {"rights", qint64(user.rights)}};
    fields.setBytes("oldNumber", wireText(oldNumber));
    fields.setBytes("name", wireText(user.name));
    fields.setBytes("number", wireText(user.number));
    fields.setBytes("access", accessBytes(user));
    const Result<Fields> reply = m_link.call('!', "USER", fields);
    if (!reply) {
        return inContext(
            QCoreApplication::translate("cambench::comm", "writing user \"%1\" (!USER)")
                .arg(user.name),
            reply.error());
    }
    return success();
}

Status AsciiCamCon::deleteUser(const QString& number) {
    Fields fields;
    fields.setBytes("oldNumber", wireText(number));
    fields.setBytes("number", QByteArrayLiteral("DEL"));
    fields.setBytes("access", QByteArray(kAccessBytes, '\0'));
    const Result<Fields> reply = m_link.call('!', "USER", fields);
    if (!reply)
        return inContext(QCoreApplication::translate("cambench::comm", "deleting a user (!USER)"),
                         reply.error());
    return success();
}

}  // namespace cambench::comm
