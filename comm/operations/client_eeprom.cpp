#include "camcon_client.h"
#include "client_support.h"

#include "model/eeprom_image_file.h"

#include <QDateTime>

namespace cambench::comm {

using namespace client;

namespace {

constexpr quint16 kEndBlock = 0xFFFF;
constexpr qint32 kWrongBlockOrder = -43;  // manual 4.6.1

QString hex4(int number) {
    return QStringLiteral("%1").arg(number, 4, 16, QChar(u'0')).toUpper();
}

}  // namespace

Result<EepromImage> CamConClient::backup(const ProgressFn& progress) {
    Result<DeviceInfo> info = readInfo();
    if (!info) return info.error();
    EepromImage image;
    image.device = std::move(info).value();
    image.taken = QDateTime::currentDateTimeUtc();
    image.toolVersion = QStringLiteral(CAMBENCH_VERSION);
    // The device does not say how much it holds; its EEPROM size bounds it.
    const qint64 estimate = qMax<qint64>(image.device.serialEepromSize, 0);
    qint64 bytes = 0;
    for (int number = 0; number < kEndBlock; ++number) {
        if (progress) progress(qMin(bytes, estimate), estimate);
        const Result<Fields> reply = m_link.call('?', "EE", Fields{{"block", qint64(number)}});
        if (!reply) {
            return inContext(QStringLiteral("reading EEPROM block %1 (?EE)").arg(hex4(number)),
                             reply.error());
        }
        const qint64 replyNumber = reply->num("block");
        if (replyNumber == kEndBlock) {
            if (number == 0) {
                return Error::communication(
                    QStringLiteral("the device sent no EEPROM block 0000; check the device"));
            }
            if (progress) progress(estimate, estimate);
            return image;
        }
        if (replyNumber != number) {
            return Error::communication(
                QStringLiteral("asked for EEPROM block %1, the device sent block %2; try again")
                    .arg(hex4(number), hex4(int(replyNumber))));
        }
        image.blocks.append(EepromBlock{quint16(number), reply->bytes("data")});
        // Each block must pass the length rule (128 bytes for 0000, the
        // nibble rule after it) before the next one is worth reading.
        const Status blocks = checkImageBlocks(
            number == 0 ? image.blocks : QList<EepromBlock>{image.blocks.first(), image.blocks.last()});
        if (!blocks) {
            return Error::communication(
                QStringLiteral("the device sent a malformed EEPROM block: %1; try again")
                    .arg(blocks.error().message));
        }
        bytes += image.blocks.last().data.size();
    }
    return Error::communication(
        QStringLiteral("the device sent EEPROM blocks up to FFFE without the end marker FFFF; "
                       "check the device"));
}

Status CamConClient::restore(const EepromImage& image, const ProgressFn& progress) {
    if (image.blocks.isEmpty() || image.blocks.first().number != 0) {
        return Error::invalidData(
            QStringLiteral("the EEPROM image does not start with block 0000; nothing was sent"));
    }
    const int total = int(image.blocks.size()) + 1;  // + the empty end block
    const int longTimeout = m_link.settings().longTimeoutMs;
    const QString again =
        QStringLiteral("Running the same restore again is safe: it starts by erasing the device.");

    for (int i = 0; i <= image.blocks.size(); ++i) {
        if (progress) progress(i, total);
        const bool endBlock = i == image.blocks.size();
        const int number = endBlock ? image.blocks.last().number + 1 : image.blocks.at(i).number;
        Fields fields{{"block", qint64(number)}};
        fields.setBytes("data", endBlock ? QByteArray() : image.blocks.at(i).data);
        // Block 0000 erases the EEPROM and the end block starts the device:
        // both may take far longer than an ordinary reply.
        const bool slow = i == 0 || endBlock;
        const int retriesBefore = m_link.stats().retries;
        const Result<Fields> reply = m_link.call('!', "EE", fields, slow ? longTimeout : 0);
        if (reply) continue;
        // Standard framing has no block numbers: when the acknowledgement
        // of a block was lost, the retry sends the same block again and the
        // device, which stored it already, answers "wrong order" (-43).
        const bool retried = m_link.stats().retries != retriesBefore;
        if (i > 0 && retried && reply.error().kind == ErrorKind::DeviceError &&
            reply.error().deviceCode == kWrongBlockOrder) {
            continue;
        }
        QString state;
        if (i == 0) {
            state = QStringLiteral("The device may already be ERASED (block 0000 starts the "
                                   "erase).");
        } else if (!endBlock) {
            state = QStringLiteral("The device is now ERASED: it holds only the blocks before "
                                   "%1 and does not run.")
                        .arg(hex4(number));
        } else {
            state = QStringLiteral("The device holds every block but did not confirm that it "
                                   "started.");
        }
        return inContext(
            QStringLiteral("restore failed at EEPROM block %1 of %2 (!EE%3). %4 %5 Cause")
                .arg(i + 1)
                .arg(total)
                .arg(hex4(number), state, again),
            reply.error());
    }
    if (progress) progress(total, total);
    return success();
}

}  // namespace cambench::comm
