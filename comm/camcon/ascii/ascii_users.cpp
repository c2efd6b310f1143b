#include "ascii_camcon.h"

#include <QCoreApplication>
#include "ascii_support.h"

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

// Walks of the user list before giving up: each restarts after a step that
// may have been executed twice.
constexpr int kMaxWalks = 5;

// One walk from ?USER00 to the empty entry, or to the first step that went
// out more than once where the device does not answer repeats without
// executing them (`lostPlace`: its list may have skipped an entry).
struct Walk {
    QList<User> users;
    QString lostPlace;  // why the walk cannot be trusted; empty when it can
};

Result<Walk> walkUsers(AsciiLink& link) {
    Walk walk;
    for (int i = 0; i <= kMaxUsers; ++i) {
        const Result<Fields> reply =
            link.call('?', "USER", Fields{{"index", qint64(i == 0 ? 0 : 1)}});
        if (!reply) {
            return inContext(
                QCoreApplication::translate("cambench::comm", "reading user entry %1 (?USER)")
                    .arg(i + 1),
                reply.error());
        }
        if (i > 0 && link.lastCallMayHaveActedTwice()) {
            walk.lostPlace =
                QCoreApplication::translate(
                    "cambench::comm", "the step to entry %1 was sent again after a lost reply")
                    .arg(i + 1);
            return walk;
        }
        if (reply->bytes("name").isEmpty() && reply->bytes("number").isEmpty()) return walk;
        if (i == kMaxUsers) break;
        walk.users.append(userFrom(*reply));
    }
    return Error::communication(
        QCoreApplication::translate(
            "cambench::comm",
            "reading the users: the device lists more than %1 entries and no end; "
            "check the device")
            .arg(kMaxUsers));
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
    // ?USER00 starts the walk, ?USER01 steps the device's cursor to the next
    // entry. A step sent twice (its reply lost, Standard framing) may have
    // stepped twice and skipped an entry: the walk then starts over, a
    // bounded number of times, and never returns a list it is unsure of.
    QString lastProblem;
    for (int attempt = 1; attempt <= kMaxWalks; ++attempt) {
        Result<Walk> walk = walkUsers(m_link);
        if (!walk) return walk.error();
        if (walk->lostPlace.isEmpty()) return std::move(walk->users);
        lastProblem = walk->lostPlace;
    }
    return Error::communication(
        QCoreApplication::translate(
            "cambench::comm",
            "reading the users: %1 walks through the list lost their place (%2); the "
            "list may be incomplete, so none is shown; check the cable and try again")
            .arg(kMaxWalks)
            .arg(lastProblem));
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
