#include "model/camcon/eeprom_image_file.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

using namespace cambench;

namespace {

EepromBlock block(quint16 number, QByteArray data) {
    return {number, std::move(data)};
}

// A later block whose first byte carries its length: nibble * 6 bytes.
QByteArray sized(int nibble, char fill) {
    QByteArray data(nibble * 6, fill);
    data[0] = char(nibble << 4 | 0x05);
    return data;
}

EepromImage sampleImage() {
    EepromImage image;
    image.device.epromDate = QStringLiteral("11.10.1994");
    image.device.deviceNumber = 7;
    image.device.outputs = 48;
    image.device.programs = 64;
    image.device.minPosition = -100;
    image.device.maxPosition = 3599;
    image.taken = QDateTime(QDate(2024, 5, 17), QTime(13, 45, 12, 250), Qt::UTC);
    image.toolVersion = QStringLiteral("0.1.0");
    QByteArray basic(128, '\0');
    for (int i = 0; i < basic.size(); ++i) basic[i] = char(i * 7);
    basic[5] = '\r';
    basic[6] = '\x1b';
    image.blocks = {block(0, basic), block(1, sized(2, 'a')), block(2, sized(15, '\xff')),
                    block(3, sized(1, '\0'))};
    return image;
}

QJsonObject sampleObject() {
    return QJsonDocument::fromJson(eepromImageToJson(sampleImage())).object();
}

// Recomputes the hash, as someone would who edits the file with intent.
QByteArray resealed(QJsonObject object) {
    object.remove(QStringLiteral("sha256"));
    const QByteArray hash =
        QCryptographicHash::hash(QJsonDocument(object).toJson(QJsonDocument::Compact),
                                 QCryptographicHash::Sha256)
            .toHex();
    object.insert(QStringLiteral("sha256"), QString::fromLatin1(hash));
    return QJsonDocument(object).toJson();
}

QJsonObject withBlocks(const QJsonArray& blocks) {
    QJsonObject object = sampleObject();
    object.insert(QStringLiteral("blocks"), blocks);
    return object;
}

QJsonObject blockJson(int number, const QByteArray& data) {
    return {{QStringLiteral("number"), number},
            {QStringLiteral("data"), QString::fromLatin1(data.toHex())}};
}

QString loadError(const QByteArray& bytes) {
    const Result<EepromImage> result = eepromImageFromJson(bytes);
    return result.ok() ? QString() : result.error().message;
}

}  // namespace

class TestEepromImageFile : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void saveAndLoadRoundTrip() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("backup.json"));
        const EepromImage image = sampleImage();
        const Status saved = saveEepromImage(path, image);
        QVERIFY2(saved.ok(), qPrintable(saved.error().message));
        const Result<EepromImage> loaded = loadEepromImage(path);
        QVERIFY2(loaded.ok(), qPrintable(loaded.error().message));
        QCOMPARE(loaded->device, image.device);
        QCOMPARE(loaded->taken, image.taken);
        QCOMPARE(loaded->toolVersion, image.toolVersion);
        QCOMPARE(loaded->blocks, image.blocks);
        QCOMPARE(loaded->totalBytes(), 128 + 12 + 90 + 6);
    }

    void fileCarriesHeaderAndHash() {
        const QJsonObject object = sampleObject();
        QCOMPARE(object.value(QStringLiteral("format")).toString(),
                 QStringLiteral("cambench-eeprom-image"));
        QCOMPARE(object.value(QStringLiteral("version")).toInt(), kEepromImageFormatVersion);
        QCOMPARE(object.value(QStringLiteral("tool")).toString(), QStringLiteral("CamBench 0.1.0"));
        QCOMPARE(object.value(QStringLiteral("taken")).toString(),
                 QStringLiteral("2024-05-17T13:45:12.250Z"));
        QCOMPARE(object.value(QStringLiteral("device"))[QStringLiteral("epromDate")].toString(),
                 QStringLiteral("11.10.1994"));
        QCOMPARE(object.value(QStringLiteral("sha256")).toString().size(), 64);
        // The same image always gives the same file.
        QCOMPARE(eepromImageToJson(sampleImage()), eepromImageToJson(sampleImage()));
    }

    void tamperedFileIsRejected() {
        QByteArray bytes = eepromImageToJson(sampleImage());
        const int at = bytes.indexOf("\"data\": \"") + 10;
        bytes[at] = bytes[at] == '0' ? '1' : '0';
        QVERIFY2(loadError(bytes).contains(QStringLiteral("changed or damaged")),
                 qPrintable(loadError(bytes)));

        QJsonObject object = sampleObject();
        object.insert(QStringLiteral("tool"), QStringLiteral("CamBench 9.9.9"));
        QVERIFY(loadError(QJsonDocument(object).toJson())
                    .contains(QStringLiteral("changed or damaged")));
    }

    void missingHashIsRejected() {
        QJsonObject object = sampleObject();
        object.remove(QStringLiteral("sha256"));
        QVERIFY(loadError(QJsonDocument(object).toJson()).contains(QStringLiteral("sha256")));
    }

    void truncatedFileIsRejected() {
        const QByteArray bytes = eepromImageToJson(sampleImage());
        const QString error = loadError(bytes.left(bytes.size() - 20));
        QVERIFY2(error.contains(QStringLiteral("not valid JSON")), qPrintable(error));
        QVERIFY(!loadError(QByteArray()).isEmpty());
    }

    void foreignJsonIsRejected() {
        QVERIFY(loadError(R"({"format":"cambench-project","version":1})")
                    .contains(QStringLiteral("not a CamBench EEPROM image")));
        QVERIFY(loadError(R"({"dependencies":{}})")
                    .contains(QStringLiteral("not a CamBench EEPROM image")));
    }

    void newerVersionIsRejectedClearly() {
        QJsonObject object = sampleObject();
        object.insert(QStringLiteral("version"), kEepromImageFormatVersion + 1);
        const QString error = loadError(resealed(object));
        QVERIFY2(error.contains(QStringLiteral("newer CamBench")), qPrintable(error));
    }

    void badBlockLengthNamesTheBlock() {
        QByteArray data = sized(2, 'a');
        data.chop(1);
        const QString error =
            loadError(resealed(withBlocks({blockJson(0, QByteArray(128, '\0')),
                                           blockJson(1, sized(1, 'x')), blockJson(2, data)})));
        QVERIFY2(error.contains(QStringLiteral("Block 0002")), qPrintable(error));
        QVERIFY(error.contains(QStringLiteral("11 bytes")));
        QVERIFY(error.contains(QStringLiteral("says 12")));
    }

    void zeroLengthNibbleIsRejected() {
        QByteArray data(6, '\x0f');
        const QString error = loadError(
            resealed(withBlocks({blockJson(0, QByteArray(128, '\0')), blockJson(1, data)})));
        QVERIFY2(error.contains(QStringLiteral("Block 0001")), qPrintable(error));
        QVERIFY(error.contains(QStringLiteral("upper 4 bits are 0")));
    }

    void basicBlockMustBe128Bytes() {
        const QString error =
            loadError(resealed(withBlocks({blockJson(0, QByteArray(127, '\0'))})));
        QVERIFY2(error.contains(QStringLiteral("127 bytes")), qPrintable(error));
    }

    void numbersMustAscendFromZero() {
        QString error = loadError(
            resealed(withBlocks({blockJson(0, QByteArray(128, '\0')), blockJson(2, sized(1, 'a')),
                                 blockJson(1, sized(1, 'b'))})));
        QVERIFY2(error.contains(QStringLiteral("Block 0001")), qPrintable(error));
        QVERIFY(error.contains(QStringLiteral("ascend")));
        error = loadError(resealed(withBlocks({blockJson(1, sized(1, 'a'))})));
        QVERIFY2(error.contains(QStringLiteral("does not start with block 0000")),
                 qPrintable(error));
        error = loadError(resealed(withBlocks({})));
        QVERIFY(error.contains(QStringLiteral("no blocks")));
    }

    void badHexDataIsRejected() {
        QJsonObject bad = blockJson(0, QByteArray(128, '\0'));
        bad.insert(QStringLiteral("data"), QStringLiteral("zz"));
        const QString error = loadError(resealed(withBlocks({bad})));
        QVERIFY2(error.startsWith(QStringLiteral("blocks[0].data: ")), qPrintable(error));
    }

    void checkImageBlocksAcceptsValidAndRejectsDuplicates() {
        QVERIFY(checkImageBlocks(sampleImage().blocks).ok());
        QList<EepromBlock> blocks = sampleImage().blocks;
        blocks[2].number = 1;
        QVERIFY(!checkImageBlocks(blocks).ok());
    }

    void invalidImageIsNotSaved() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("bad.json"));
        EepromImage image = sampleImage();
        image.blocks[1].data.chop(1);
        QVERIFY(!saveEepromImage(path, image).ok());
        QVERIFY(!QFile::exists(path));
    }

    void identityMismatchListsDifferences() {
        const DeviceInfo image = sampleImage().device;
        QVERIFY(identityMismatch(image, image).isEmpty());
        DeviceInfo device = image;
        device.ramFree = 1000;  // changes by itself: not part of the identity
        device.temperature = 40;
        device.programmedCams = 7;  // the content, which a restore replaces
        QVERIFY(identityMismatch(image, device).isEmpty());
        device.epromDate = QStringLiteral("01.02.1999");
        device.outputs = 32;
        device.maxPosition = 359;
        device.deviceNumber = 9;  // another device on the bus
        const QStringList differences = identityMismatch(image, device);
        QCOMPARE(differences.size(), 4);  // in the identity's key order
        QVERIFY2(differences.at(0).contains(QStringLiteral("3599")), qPrintable(differences.at(0)));
        QVERIFY(differences.at(1).contains(QStringLiteral("device: image ")));
        QVERIFY(differences.at(2).contains(QStringLiteral("01.02.1999")));
        QVERIFY(differences.at(3).contains(QStringLiteral("outputs: image 48, device 32")));
    }
};

QTEST_GUILESS_MAIN(TestEepromImageFile)
#include "tst_eeprom_image_file.moc"
