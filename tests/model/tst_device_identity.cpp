// Issue 35, item 8: who a device is, and whether a backup may go to the
// device that answers: only its own, or the one the person accepted as its
// replacement; a backup without an identity (older than the record) is
// refused the same way until the person says so. Both identities are named.
#include "model/device_identity.h"

#include <QtTest>

using namespace cambench;

namespace {

DeviceIdentity drive(const QString& serial, const QString& type = QStringLiteral("S025V2")) {
    DeviceIdentity identity;
    identity.set(QStringLiteral("type"), type);
    identity.set(QStringLiteral("serial"), serial);
    return identity;
}

}  // namespace

class TestDeviceIdentity : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void textAndJsonInKeyOrder() {
        const DeviceIdentity a = drive(QStringLiteral("C3-1"));
        QCOMPARE(a.text(), QStringLiteral("serial C3-1, type S025V2"));
        QCOMPARE(DeviceIdentity().text(), QStringLiteral("not recorded"));
        const Result<DeviceIdentity> back =
            DeviceIdentity::fromJson(a.toJson(), QStringLiteral("x"));
        QVERIFY(back.ok());
        QCOMPARE(*back, a);
        QVERIFY(!DeviceIdentity::fromJson(QJsonValue(QStringLiteral("text")), QStringLiteral("x"))
                     .ok());
    }

    void anotherDeviceNamesWhatDiffers() {
        QCOMPARE(anotherDeviceText(drive(QStringLiteral("C3-1")), drive(QStringLiteral("C3-2"))),
                 QStringLiteral("another device answers: expected serial C3-1, found serial C3-2"));
        DeviceIdentity more = drive(QStringLiteral("C3-1"));
        more.set(QStringLiteral("axes"), QStringLiteral("1:0/1"));
        QCOMPARE(anotherDeviceText(more, drive(QStringLiteral("C3-1"), QStringLiteral("S150V4"))),
                 QStringLiteral("another device answers: expected axes 1:0/1, type S025V2, found "
                                "axes none, type S150V4"));
    }

    void restoreOnlyToItsOwnDeviceOrAnAcceptedReplacement() {
        const DeviceIdentity own = drive(QStringLiteral("C3-1"));
        const DeviceIdentity other = drive(QStringLiteral("C3-2"));
        const QString file = QStringLiteral("feed.json");
        QVERIFY(checkRestoreTarget(own, own, {}, file).ok());
        const Status refused = checkRestoreTarget(own, other, {}, file);
        QVERIFY(!refused.ok());
        QCOMPARE(refused.error().kind, ErrorKind::InvalidData);
        QVERIFY2(refused.error().message.startsWith(
                     QLatin1String("feed.json was taken from another device: another device "
                                   "answers: expected serial C3-1, found serial C3-2 (the "
                                   "backup's device: serial C3-1, type S025V2; the device "
                                   "answering: serial C3-2, type S025V2). Nothing was written.")),
                 qPrintable(refused.error().message));
        QVERIFY(checkRestoreTarget(own, other, ReplacementConsent::any(), file).ok());
        QVERIFY(checkRestoreTarget(own, other, ReplacementConsent::of(other), file).ok());
        // Accepted for a device that no longer answers: refused.
        const DeviceIdentity third = drive(QStringLiteral("C3-3"));
        QVERIFY(!checkRestoreTarget(own, third, ReplacementConsent::of(other), file).ok());
    }

    void aBackupWithoutIdentityNeedsTheWordOfThePerson() {
        const DeviceIdentity device = drive(QStringLiteral("C3-1"));
        const Status refused = checkRestoreTarget({}, device, {}, QStringLiteral("old.json"));
        QVERIFY(!refused.ok());
        QVERIFY2(refused.error().message.contains(QLatin1String("records no identity")),
                 qPrintable(refused.error().message));
        QVERIFY(refused.error().message.contains(QLatin1String("serial C3-1, type S025V2")));
        QVERIFY(checkRestoreTarget({}, device, ReplacementConsent::any(), {}).ok());
    }
};

QTEST_GUILESS_MAIN(TestDeviceIdentity)
#include "tst_device_identity.moc"
