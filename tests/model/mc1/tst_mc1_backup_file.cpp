// Issue 14: the MC-1 backup file - written and read back unchanged, and
// every damage or foreign content refused with where it is.
#include "model/mc1/mc1_backup_file.h"

#include <QCryptographicHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>
#include <QTimeZone>

using namespace cambench;

namespace {

Mc1Backup sample(const QString& variant = QStringLiteral("mc200v2")) {
    Mc1Backup backup;
    backup.variant = variant;
    backup.taken = QDateTime(QDate(2026, 11, 26), QTime(12, 0), Qt::UTC);
    backup.toolVersion = QStringLiteral("0.1.0");
    backup.variables = {{1, -250}, {2, 7}, {1000, 2147483647}};
    backup.flagPage = 0;
    backup.flags = QByteArray(256, '\0');
    backup.flags[3] = char(0x81);
    backup.memory = {{0x1000, QByteArray("\x01\x02\x03", 3)}, {0x2000, QByteArray(130, 'x')}};
    return backup;
}

// The file with one member changed and its checksum made to fit again.
QByteArray edited(const QByteArray& json, const QString& key, const QJsonValue& value) {
    QJsonObject root = QJsonDocument::fromJson(json).object();
    root.insert(key, value);
    root.remove(QStringLiteral("sha256"));
    const QByteArray hash =
        QCryptographicHash::hash(QJsonDocument(root).toJson(QJsonDocument::Compact),
                                 QCryptographicHash::Sha256)
            .toHex();
    root.insert(QStringLiteral("sha256"), QString::fromLatin1(hash));
    return QJsonDocument(root).toJson();
}

}  // namespace

class TestMc1BackupFile : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void roundTrip() {
        const Mc1Backup backup = sample();
        const Result<Mc1Backup> read = mc1BackupFromJson(mc1BackupToJson(backup));
        QVERIFY2(read.ok(), qPrintable(read.error().message));
        QCOMPARE(read->variant, backup.variant);
        QCOMPARE(read->taken, backup.taken);
        QCOMPARE(read->variables, backup.variables);
        QCOMPARE(read->flags, backup.flags);
        QCOMPARE(read->memory.size(), 2);
        QCOMPARE(read->memory.at(1).data, backup.memory.at(1).data);
        QCOMPARE(mc1BackupToJson(*read), mc1BackupToJson(backup));  // byte for byte
    }

    void aChangedFileIsRefused() {
        QByteArray json = mc1BackupToJson(sample());
        json.replace("-250", "-251");
        const Result<Mc1Backup> read = mc1BackupFromJson(json);
        QCOMPARE(read.error().kind, ErrorKind::InvalidData);
        QVERIFY2(read.error().message.contains(QLatin1String("SHA-256")),
                 qPrintable(read.error().message));
    }

    void contentIsCheckedWhereItIs() {
        const QByteArray json = mc1BackupToJson(sample());
        struct Case {
            const char* key;
            QJsonValue value;
            const char* says;
        };
        const Case cases[] = {
            {"variant", QStringLiteral("mc300"), "variant"},
            {"variables", QJsonArray{QJsonArray{1, 2}, QJsonArray{1, 3}}, "V1 a second time"},
            {"variables", QJsonArray{QJsonArray{1}}, "variables[0]"},
            {"flags", QStringLiteral("00ff"), "2 bytes"},
            {"flags", QStringLiteral("0g"), "hexadecimal"},
            {"memory", QJsonArray{QJsonObject{{"address", 65535}, {"data", "0102"}}}, "do not fit"},
            {"memory",
             QJsonArray{QJsonObject{{"address", 16}, {"data", "0102"}},
                        QJsonObject{{"address", 17}, {"data", "01"}}},
             "overlaps"},
        };
        for (const Case& c : cases) {
            const Result<Mc1Backup> read =
                mc1BackupFromJson(edited(json, QLatin1String(c.key), c.value));
            QVERIFY2(!read.ok(), c.key);
            QCOMPARE(read.error().kind, ErrorKind::InvalidData);
            QVERIFY2(read.error().message.contains(QLatin1String(c.says)),
                     qPrintable(read.error().message));
        }
        // 24-bit values on an MC100.
        Mc1Backup mc100 = sample(QStringLiteral("mc100v1"));
        mc100.variables = {{1, 8388608}};
        const Result<Mc1Backup> wide = mc1BackupFromJson(mc1BackupToJson(mc100));
        QVERIFY2(wide.error().message.contains(QLatin1String("24 bits")),
                 qPrintable(wide.error().message));
    }

    void anotherFamilysFileIsNamed() {
        const QByteArray json =
            edited(mc1BackupToJson(sample()), QStringLiteral("family"), QStringLiteral("camcon"));
        const Result<Mc1Backup> read = mc1BackupFromJson(json);
        QVERIFY2(read.error().message.contains(QLatin1String("camcon")),
                 qPrintable(read.error().message));
    }
};

QTEST_GUILESS_MAIN(TestMc1BackupFile)
#include "tst_mc1_backup_file.moc"
