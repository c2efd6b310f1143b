#include "model/atomic_file.h"
#include "model/file_read.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace cambench;

class TestAtomicFile : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void writesAndReplacesContent() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("a.txt"));
        QVERIFY(writeFileAtomically(path, "first").ok());
        QVERIFY(writeFileAtomically(path, "second").ok());
        QCOMPARE(*readFileBytes(path), QByteArray("second"));
    }

    void failureNamesFileAndSaysNothingChanged() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("no/such/dir/a.txt"));
        const Status status = writeFileAtomically(path, "x");
        QVERIFY(!status.ok());
        QVERIFY(status.error().message.contains(path));
        QVERIFY(status.error().message.contains(QStringLiteral("not changed")));
    }

    void readRefusesDirectoriesMissingAndOversizedFiles() {
        QTemporaryDir dir;
        QVERIFY(!readFileBytes(dir.path()).ok());
        QVERIFY(!readFileBytes(dir.filePath(QStringLiteral("missing"))).ok());
        const QString path = dir.filePath(QStringLiteral("big"));
        QVERIFY(writeFileAtomically(path, QByteArray(100, 'x')).ok());
        QVERIFY(readFileBytes(path, 100).ok());
        const Result<QByteArray> tooBig = readFileBytes(path, 99);
        QVERIFY(!tooBig.ok());
        QVERIFY(tooBig.error().message.contains(QStringLiteral("larger than 99 bytes")));
    }
};

QTEST_GUILESS_MAIN(TestAtomicFile)
#include "tst_atomic_file.moc"
