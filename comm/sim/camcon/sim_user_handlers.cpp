#include "sim_device.h"
#include "sim_handlers.h"

#include <algorithm>

namespace cambench::comm {

namespace {

const QByteArray kDelete = QByteArrayLiteral("DEL");

Fields userFields(const SimUser& user) {
    Fields fields;
    fields.setBytes("name", user.name)
        .setBytes("number", user.number)
        .setBytes("access", user.access);
    fields.set("all", user.allOutputs ? 1 : 0).set("rights", user.rights);
    return fields;
}

SimUser userFrom(const Fields& r) {
    SimUser user;
    user.name = r.bytes("name");
    user.number = r.bytes("number");
    user.access = r.bytes("access").leftJustified(SimUser::kAccessBytes, '\0', true);
    user.allOutputs = r.num("all") != 0;
    user.rights = quint32(r.num("rights"));
    return user;
}

qsizetype findUser(const QList<SimUser>& users, const QByteArray& number) {
    const auto it = std::find_if(users.begin(), users.end(),
                                 [&](const SimUser& u) { return u.number == number; });
    return it == users.end() ? -1 : it - users.begin();
}

// !USER (notes 4): no old number creates, "DEL" deletes, otherwise modifies.
qint32 writeUser(QList<SimUser>& users, int maxUsers, const Fields& r) {
    const QByteArray oldNumber = r.bytes("oldNumber");
    const SimUser user = userFrom(r);
    const qsizetype existing = oldNumber.isEmpty() ? -1 : findUser(users, oldNumber);
    if (!oldNumber.isEmpty() && existing < 0) return sim_errors::kUnknown;
    if (user.number == kDelete) {
        if (existing < 0) return sim_errors::kUnknown;
        users.removeAt(existing);
        return 0;
    }
    if (user.number.isEmpty()) return sim_errors::kUnknown;
    const qsizetype clash = findUser(users, user.number);
    if (clash >= 0 && clash != existing) return sim_errors::kUnknown;
    if (existing >= 0) {
        users[existing] = user;
        return 0;
    }
    if (users.size() >= maxUsers) return sim_errors::kEepromFull;
    users.append(user);
    return 0;
}

}  // namespace

void registerUserHandlers(SimDevice& d) {
    // ?USER00 starts the walk, ?USER01 steps on; past the end the name and
    // number are all NUL (notes 4).
    d.addHandler(kQuery, "USER", [&d](const Fields& r) {
        const qint64 index = r.num("index");
        if (index > 1) return SimResult::error(sim_errors::kUnknown);
        int& cursor = d.runtime().userCursor;
        cursor = index == 0 ? 0 : cursor + 1;
        const QList<SimUser>& users = d.state().users;
        if (cursor >= users.size()) {
            cursor = int(users.size());
            return SimResult::data(userFields(SimUser()));
        }
        return SimResult::data(userFields(users.at(cursor)));
    });
    d.addHandler(kCommand, "USER", [&d](const Fields& r) {
        return SimResult::okOr(writeUser(d.state().users, d.profile().maxUsers, r));
    });
}

}  // namespace cambench::comm
