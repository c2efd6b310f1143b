// UserCopies: the users in SectionCopies' shape, with the order the users
// page shows and the number each user has on the device. Two devices that
// differ: A and B share the number 22222 with different users, so that a
// device copy or a device number from the wrong one would show.
#include "model/camcon/user_copies.h"

#include <QtTest>

using namespace cambench;

namespace {

User user(const QString& name, const QString& number, quint32 rights = 0) {
    User u;
    u.name = name;
    u.number = number;
    u.rights = rights;
    return u;
}

const QList<User> kDeviceA{user("Anna", "11111"), user("Ben", "22222"), user("Cleo", "33333")};
const QList<User> kDeviceB{user("Dora", "44444"), user("Emil", "22222", User::Programming)};

QStringList names(const UserCopies& users) {
    QStringList all;
    for (const UserCopies::EditedUser& edited : users.rows()) all << edited.user.name;
    return all;
}

QStringList deviceNumbers(const UserCopies& users) {
    QStringList all;
    for (const UserCopies::EditedUser& edited : users.rows()) all << edited.deviceNumber;
    return all;
}

UserCopies readFromA() {
    UserCopies users;
    users.merge(kDeviceA, ValueSource::Device, false);
    return users;
}

}  // namespace

class TestUserCopies : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aReadShowsTheDevicesUsersInItsOrder() {
        UserCopies users;
        int changes = 0;
        users.onChange = [&changes] { ++changes; };
        QVERIFY(!users.known());
        users.merge(kDeviceA, ValueSource::Device, false);
        QVERIFY(users.known());
        QCOMPARE(changes, 1);
        QCOMPARE(names(users), QStringList({"Anna", "Ben", "Cleo"}));
        QCOMPARE(deviceNumbers(users), QStringList({"11111", "22222", "33333"}));
        QCOMPARE(users.device(), kDeviceA);
        QCOMPARE(users.changedCount(), 0);
        QVERIFY(users.deletedNumbers().isEmpty());
    }

    void aNewUserIsChangedAndNotOnTheDevice() {
        UserCopies users = readFromA();
        const int index = users.add(user("Dora", "44444"));
        QCOMPARE(index, 3);
        QVERIFY(users.isChanged(index));
        QCOMPARE(users.row(index).deviceNumber, QString());
        QCOMPARE(users.changedCount(), 1);
        QVERIFY(!users.deviceUser("44444"));
        // Removing a user not on the device leaves nothing to delete.
        users.remove(index);
        QCOMPARE(users.changedCount(), 0);
        QVERIFY(users.deletedNumbers().isEmpty());
    }

    void anEditBackToTheDevicesUserIsNone() {
        UserCopies users = readFromA();
        User renamed = users.row(1).user;
        renamed.name = "Benno";
        users.set(1, renamed);
        QVERIFY(users.isChanged(1));
        QCOMPARE(users.row(1).deviceNumber, QString("22222"));
        QCOMPARE(users.deviceUser("22222")->name, QString("Ben"));
        users.set(1, kDeviceA.at(1));
        QVERIFY(!users.isChanged(1));
        QCOMPARE(users.changedCount(), 0);
    }

    void aRemovedDeviceUserIsToBeDeleted() {
        UserCopies users = readFromA();
        users.remove(0);
        QCOMPARE(names(users), QStringList({"Ben", "Cleo"}));
        QCOMPARE(users.deletedNumbers(), QStringList{"11111"});
        QCOMPARE(users.changedCount(), 1);
        // The write: the device's user is gone, and with it the deletion.
        users.setDevice(-1, "11111", std::nullopt);
        QVERIFY(users.deletedNumbers().isEmpty());
        QCOMPARE(users.changedCount(), 0);
        QCOMPARE(users.device(), QList<User>({kDeviceA.at(1), kDeviceA.at(2)}));
    }

    void aWrittenNewUserTakesItsDeviceNumber() {
        UserCopies users = readFromA();
        const int index = users.add(user("Dora", "44444"));
        users.setDevice(index, QString(), user("Dora", "44444"));
        QVERIFY(!users.isChanged(index));
        QCOMPARE(users.row(index).deviceNumber, QString("44444"));
        QCOMPARE(users.changedCount(), 0);
        // A failed deletion leaves it to do.
        users.remove(0);
        users.setDevice(-1, "11111", kDeviceA.at(0));
        QCOMPARE(users.deletedNumbers(), QStringList{"11111"});
    }

    void aReadOfBKeepsEditsOnlyWhenAsked() {
        for (const bool keepEdits : {true, false}) {
            UserCopies users = readFromA();
            User renamed = users.row(1).user;  // 22222, on B too
            renamed.name = "Benno";
            users.set(1, renamed);
            User cleo = users.row(2).user;  // 33333, not on B
            cleo.rights = User::UserMenu;
            users.set(2, cleo);
            users.remove(0);  // 11111, not on B
            users.add(user("Fritz", ""));
            users.merge(kDeviceB, ValueSource::Device, keepEdits);
            QCOMPARE(users.device(), kDeviceB);
            QVERIFY(users.deletedNumbers().isEmpty());
            if (!keepEdits) {
                QCOMPARE(names(users), QStringList({"Dora", "Emil"}));
                QCOMPARE(users.changedCount(), 0);
                continue;
            }
            // B's list, the kept edit in place of its user, then the users
            // B does not have, as new ones.
            QCOMPARE(names(users), QStringList({"Dora", "Benno", "Cleo", "Fritz"}));
            QCOMPARE(deviceNumbers(users), QStringList({"44444", "22222", "", ""}));
            QCOMPARE(users.changedCount(), 3);
        }
    }

    void aProjectMatchesUsersByNumberElseByName() {
        UserCopies users = readFromA();
        users.add(user("Fritz", ""));
        const QList<User> project{user("Ben", "", User::PlcMenu),     // the device's 22222
                                  user("Fritz", "", User::UserMenu),  // the new user
                                  user("Gina", "55555")};             // another new one
        users.merge(project, ValueSource::File, false);
        QCOMPARE(names(users), QStringList({"Anna", "Ben", "Cleo", "Fritz", "Gina"}));
        QCOMPARE(users.row(1).user.number, QString("22222"));
        QCOMPARE(users.row(1).user.rights, quint32(User::PlcMenu));
        QCOMPARE(users.row(3).user.rights, quint32(User::UserMenu));
        QCOMPARE(users.row(4).deviceNumber, QString());
        QCOMPARE(users.changedCount(), 3);
        // With keepEdits an edited user keeps its edit.
        users.merge({user("Ben", "22222")}, ValueSource::File, true);
        QCOMPARE(users.row(1).user.rights, quint32(User::PlcMenu));
        // A project naming a deleted user brings it back.
        users.remove(0);
        users.merge({kDeviceA.at(0)}, ValueSource::File, false);
        QVERIFY(users.deletedNumbers().isEmpty());
        QCOMPARE(names(users).last(), QString("Anna"));
        QVERIFY(!users.isChanged(int(users.size()) - 1));
    }

    void forgettingTheDeviceCarriesWhatIsAsked_data() {
        QTest::addColumn<CarryOver>("carry");
        QTest::addColumn<QStringList>("kept");
        QTest::newRow("nothing") << CarryOver::Nothing << QStringList();
        QTest::newRow("changes") << CarryOver::Changes << QStringList({"Benno", "Fritz"});
        QTest::newRow("everything")
            << CarryOver::Everything << QStringList({"Benno", "Cleo", "Fritz"});
    }
    void forgettingTheDeviceCarriesWhatIsAsked() {
        QFETCH(CarryOver, carry);
        QFETCH(QStringList, kept);
        UserCopies users = readFromA();
        users.remove(0);
        User renamed = users.row(0).user;
        renamed.name = "Benno";
        users.set(0, renamed);
        users.add(user("Fritz", ""));
        users.forgetDevice(carry);
        QVERIFY(!users.known());
        QVERIFY(users.device().isEmpty());
        QVERIFY(users.deletedNumbers().isEmpty());
        QCOMPARE(names(users), kept);
        // On the next device every carried user is a new one, to be added.
        QCOMPARE(deviceNumbers(users), QStringList(kept.size(), QString()));
        QCOMPARE(users.changedCount(), int(kept.size()));
        // B's 22222 is not A's: the carried Benno stays a user of its own.
        users.merge(kDeviceB, ValueSource::Device, true);
        QCOMPARE(names(users), QStringList({"Dora", "Emil"}) + kept);
        QCOMPARE(users.changedCount(), int(kept.size()));
    }
};

QTEST_GUILESS_MAIN(TestUserCopies)
#include "tst_user_copies.moc"
