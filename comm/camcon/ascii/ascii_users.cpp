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

QByteArray accessBytes(const User& user) {
    QByteArray bytes(kAccessBytes, '\0');
    for (int i = 0; i < kAccessOutputs && i < user.outputAccess.size(); ++i) {
        if (user.outputAccess.at(i)) bytes[i / 8] = char(quint8(bytes.at(i / 8)) | (1u << (i % 8)));
    }
    return bytes;
}

}  // namespace

Result<QList<User>> AsciiCamCon::readUsers() {
    QList<User> users;
    for (int i = 0; i <= kMaxUsers; ++i) {
        // ?USER00 asks for the first entry, ?USER01 for the next one.
        const Result<Fields> reply =
            m_link.call('?', "USER", Fields{{"index", qint64(i == 0 ? 0 : 1)}});
        if (!reply) {
            return inContext(
                QCoreApplication::translate("cambench::comm", "reading user entry %1 (?USER)")
                    .arg(i + 1),
                reply.error());
        }
        if (reply->bytes("name").isEmpty() && reply->bytes("number").isEmpty()) return users;
        if (i == kMaxUsers) break;
        users.append(userFrom(*reply));
    }
    return Error::communication(
        QCoreApplication::translate(
            "cambench::comm",
            "reading the users: the device lists more than %1 entries and no end; "
            "check the device")
            .arg(kMaxUsers));
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
