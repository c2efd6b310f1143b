// SectionCopies: the one shape of a section's edited copy and device copy
// (settings, PLC networks, dead-time modes, the table interface's sections).
// Two devices that differ: A and B, so that a device copy from the wrong one
// would show.
#include "model/camcon/section_copies.h"

#include <QString>
#include <QtTest>

using namespace cambench;

namespace {

using Copies = SectionCopies<QString, int>;

const Copies::Map kDeviceA{{"speed", 10}, {"offset", 20}, {"zero", 30}};
const Copies::Map kDeviceB{{"speed", 11}, {"offset", 20}, {"limit", 40}};

}  // namespace

class TestSectionCopies : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void anEditEqualToTheDeviceIsNone() {
        Copies copies;
        copies.merge(kDeviceA, ValueSource::Device, false);
        QVERIFY(copies.known());
        QCOMPARE(copies.changedCount(), 0);
        copies.edit("speed", 99);
        QCOMPARE(copies.value("speed"), std::optional<int>(99));
        QCOMPARE(copies.deviceValue("speed"), std::optional<int>(10));
        QVERIFY(copies.isChanged("speed"));
        copies.edit("speed", 10);
        QVERIFY(!copies.isChanged("speed"));
        QCOMPARE(copies.changedCount(), 0);
        // A value the device does not name counts as changed.
        copies.edit("limit", 5);
        QCOMPARE(copies.changedKeys(), QList<QString>{"limit"});
        QCOMPARE(copies.value("nothing"), std::nullopt);
    }

    void aWriteMakesTheEditTheDevicesValue() {
        Copies copies;
        copies.merge(kDeviceA, ValueSource::Device, false);
        copies.edit("speed", 99);
        copies.edit("offset", 98);
        copies.setDevice("speed", 99);
        QCOMPARE(copies.changedKeys(), QList<QString>{"offset"});
        QCOMPARE(copies.deviceValue("speed"), std::optional<int>(99));
    }

    void mergeFromTheDeviceKeepsEditsOnlyWhenAsked() {
        for (const bool keepEdits : {true, false}) {
            Copies copies;
            copies.merge(kDeviceA, ValueSource::Device, false);
            copies.edit("speed", 99);  // named by B: kept only with keepEdits
            copies.edit("zero", 97);   // not named by B: stays either way
            copies.merge(kDeviceB, ValueSource::Device, keepEdits);
            QCOMPARE(copies.deviceValue("speed"), std::optional<int>(11));
            QCOMPARE(copies.value("speed"), std::optional<int>(keepEdits ? 99 : 11));
            QCOMPARE(copies.value("zero"), std::optional<int>(97));
            QCOMPARE(copies.value("limit"), std::optional<int>(40));
            // merge() names items: A's "zero" stays A's device copy.
            QCOMPARE(copies.deviceValue("zero"), std::optional<int>(30));
            QCOMPARE(copies.changedCount(), keepEdits ? 2 : 1);
        }
    }

    void aKeptEditEqualToTheNewDeviceValueIsNone() {
        Copies copies;
        copies.merge(kDeviceA, ValueSource::Device, false);
        copies.edit("speed", 11);
        copies.merge(kDeviceB, ValueSource::Device, true);
        QCOMPARE(copies.changedCount(), 0);
    }

    void mergeFromAFileMakesEdits() {
        Copies copies;
        copies.merge(kDeviceA, ValueSource::Device, false);
        copies.edit("offset", 77);
        copies.merge(kDeviceB, ValueSource::File, true);
        QCOMPARE(copies.device(), kDeviceA);  // a file is no device
        QCOMPARE(copies.value("speed"), std::optional<int>(11));
        QCOMPARE(copies.value("offset"), std::optional<int>(77));  // kept
        QCOMPARE(copies.value("limit"), std::optional<int>(40));
        QCOMPARE(copies.changedKeys(), (QList<QString>{"limit", "offset", "speed"}));
        copies.merge(kDeviceB, ValueSource::File, false);
        // B's offset equals A's: no edit left there.
        QCOMPARE(copies.changedKeys(), (QList<QString>{"limit", "speed"}));
    }

    void mergeWholeForgetsWhatTheDeviceNoLongerNames() {
        Copies copies;
        copies.merge(kDeviceA, ValueSource::Device, false);
        copies.edit("offset", 50);
        copies.mergeWhole(kDeviceB, true);
        QCOMPARE(copies.device(), kDeviceB);
        QCOMPARE(copies.value("zero"), std::nullopt);
        QCOMPARE(copies.value("offset"), std::optional<int>(50));
        // An edit of an item the device lacks stays, counted.
        copies.edit("zero", 1);
        copies.mergeWhole(kDeviceA, false);
        QCOMPARE(copies.changedKeys(), QList<QString>{});
        copies.edit("limit", 2);
        copies.mergeWhole(kDeviceA, false);
        QCOMPARE(copies.changedKeys(), QList<QString>{"limit"});
    }

    void forgetDeviceCarriesWhatCarryOverSays_data() {
        QTest::addColumn<int>("carry");
        QTest::addColumn<int>("changedAfter");
        QTest::addColumn<int>("speedShown");
        QTest::newRow("nothing") << int(CarryOver::Nothing) << 0 << -1;
        QTest::newRow("changes") << int(CarryOver::Changes) << 1 << 99;
        QTest::newRow("everything") << int(CarryOver::Everything) << 3 << 99;
    }
    void forgetDeviceCarriesWhatCarryOverSays() {
        QFETCH(int, carry);
        QFETCH(int, changedAfter);
        QFETCH(int, speedShown);
        Copies copies;
        int changes = 0;
        copies.onChange = [&changes] { ++changes; };
        copies.merge(kDeviceA, ValueSource::Device, false);
        copies.edit("speed", 99);
        QCOMPARE(changes, 2);
        copies.forgetDevice(CarryOver(carry));
        QCOMPARE(changes, 3);
        QVERIFY(!copies.known());
        QVERIFY(copies.device().isEmpty());
        QCOMPARE(copies.changedCount(), changedAfter);
        QCOMPARE(copies.value("speed").value_or(-1), speedShown);
        // Device B read: Changes and Everything keep what was carried.
        copies.merge(kDeviceB, ValueSource::Device, true);
        QCOMPARE(copies.value("speed").value_or(-1), speedShown < 0 ? 11 : speedShown);
        QCOMPARE(copies.value("zero").value_or(-1),
                 CarryOver(carry) == CarryOver::Everything ? 30 : -1);
    }

    void callsThatChangeNothingTellNoOne() {
        Copies copies;
        int changes = 0;
        copies.onChange = [&changes] { ++changes; };
        copies.merge(kDeviceA, ValueSource::Device, false);
        copies.merge(kDeviceA, ValueSource::Device, false);
        copies.edit("speed", 10);
        copies.setDevice("speed", 10);
        copies.dropEdit("speed");
        QCOMPARE(changes, 1);
    }

    void aSingleValue() {
        SingleCopy<bool> lock;
        QCOMPARE(lock.value(), std::nullopt);
        lock.merge(std::optional<bool>(true), ValueSource::File, false);
        QVERIFY(lock.isChanged());  // not known on the device
        lock.merge(std::optional<bool>(false), ValueSource::Device, true);
        QCOMPARE(lock.value(), std::optional<bool>(true));
        QCOMPARE(lock.deviceValue(), std::optional<bool>(false));
        lock.merge(std::nullopt, ValueSource::Device, false);  // none arrived
        QVERIFY(lock.isChanged());
        lock.dropEdit();
        QCOMPARE(lock.value(), std::optional<bool>(false));
        QCOMPARE(lock.changedCount(), 0);
    }
};

QTEST_APPLESS_MAIN(TestSectionCopies)
#include "tst_section_copies.moc"
