#include "ascii_camcon.h"
#include "ascii_support.h"

#include "model/camcon/eeprom_image_file.h"

#include <QCoreApplication>
#include <QDateTime>

#include <optional>

namespace cambench::comm {

using namespace client;

namespace {

constexpr quint16 kEndBlock = 0xFFFF;
constexpr qint32 kWrongBlockOrder = -43;  // manual 4.6.1

// A restore that lost an acknowledgement starts over, a bounded number of times.
constexpr int kTransferAttempts = 5;

QString hex4(int number) {
    return QStringLiteral("%1").arg(number, 4, 16, QChar(u'0')).toUpper();
}

struct TransferFailure {
    int index;   // position in the transfer, 0 = block 0000
    int number;  // block number sent
    Error error;
    // The device answered "wrong order" (-43) because a block reached it
    // twice or one assumed stored had not: it ended the transfer, and
    // starting over from block 0000 (which erases first) is the way on.
    bool duplicate;
};

// Sends one !EE block. In Multiuser framing the link's retries are safe: a
// repeated block number makes the device repeat its answer. Standard framing
// has no block numbers, and a block that reached the device must not be sent
// again (it would answer -43 and end the transfer). So there a block is sent
// without the link's retries: a reply that arrived damaged still proves the
// device took the block (it answers after storing it), and only a block that
// drew no answer at all is sent again.
struct BlockSend {
    bool assumedAccepted = false;  // a damaged answer was taken as "stored"
    bool repeated = false;         // the block went out more than once
};

Result<Fields> sendBlock(ProtocolLink& link, const Fields& fields, int timeoutMs, BlockSend& send) {
    send = {};
    if (link.settings().framing == Framing::Multiuser) {
        Result<Fields> reply = link.call('!', "EE", fields, timeoutMs);
        send.repeated = link.lastAttempts() > 1;
        return reply;
    }
    const int retries = link.settings().retries;
    link.setRetries(0);
    Result<Fields> reply = link.call('!', "EE", fields, timeoutMs);
    for (int attempt = 0; !reply && attempt < retries; ++attempt) {
        if (reply.error().kind != ErrorKind::Communication) break;
        if (link.lastCallHeardDevice()) {
            send.assumedAccepted = true;
            reply = Fields{};
            break;
        }
        send.repeated = true;
        reply = link.call('!', "EE", fields, timeoutMs);
    }
    link.setRetries(retries);
    return reply;
}

// One pass: !EE0000 (erases), every block in ascending order, then the
// empty block that starts the device.
std::optional<TransferFailure> transfer(ProtocolLink& link, const EepromImage& image,
                                        const ProgressFn& progress) {
    const int total = int(image.blocks.size()) + 1;
    bool previousAssumed = false;
    for (int i = 0; i < total; ++i) {
        if (progress) progress(i, total);
        const bool endBlock = i == total - 1;
        const int number = endBlock ? image.blocks.last().number + 1 : image.blocks.at(i).number;
        Fields fields{{"block", qint64(number)}};
        fields.setBytes("data", endBlock ? QByteArray() : image.blocks.at(i).data);
        // Block 0000 erases the EEPROM and the end block starts the device:
        // both may take far longer than an ordinary reply.
        const bool slow = i == 0 || endBlock;
        BlockSend send;
        const Result<Fields> reply =
            sendBlock(link, fields, slow ? link.settings().longTimeoutMs : 0, send);
        if (reply) {
            previousAssumed = send.assumedAccepted;
            continue;
        }
        // -43 after a repeated block (the first copy was stored) or after a
        // block assumed stored that was not: the device ended the transfer,
        // and only a new pass from block 0000 goes on.
        const bool orderLost = i > 0 && reply.error().kind == ErrorKind::DeviceError &&
                               reply.error().deviceCode == kWrongBlockOrder &&
                               (send.repeated || previousAssumed);
        return TransferFailure{i, number, reply.error(), orderLost};
    }
    return std::nullopt;
}

}  // namespace

Result<EepromImage> AsciiCamCon::backup(const ProgressFn& progress) {
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
            return inContext(
                QCoreApplication::translate("cambench::comm", "reading EEPROM block %1 (?EE)")
                    .arg(hex4(number)),
                reply.error());
        }
        const qint64 replyNumber = reply->num("block");
        if (replyNumber == kEndBlock) {
            if (number == 0) {
                return Error::communication(QCoreApplication::translate(
                    "cambench::comm", "the device sent no EEPROM block 0000; check the device"));
            }
            if (progress) progress(estimate, estimate);
            return image;
        }
        if (replyNumber != number) {
            return Error::communication(
                QCoreApplication::translate(
                    "cambench::comm",
                    "asked for EEPROM block %1, the device sent block %2; try again")
                    .arg(hex4(number), hex4(int(replyNumber))));
        }
        image.blocks.append(EepromBlock{quint16(number), reply->bytes("data")});
        // Each block must pass the length rule (128 bytes for 0000, the
        // nibble rule after it) before the next one is worth reading.
        const Status blocks = checkImageBlocks(
            number == 0 ? image.blocks
                        : QList<EepromBlock>{image.blocks.first(), image.blocks.last()});
        if (!blocks) {
            return Error::communication(
                QCoreApplication::translate(
                    "cambench::comm", "the device sent a malformed EEPROM block: %1; try again")
                    .arg(blocks.error().message));
        }
        bytes += image.blocks.last().data.size();
    }
    return Error::communication(QCoreApplication::translate(
        "cambench::comm",
        "the device sent EEPROM blocks up to FFFE without the end marker FFFF; "
        "check the device"));
}

Status AsciiCamCon::restore(const EepromImage& image, const ProgressFn& progress) {
    if (image.blocks.isEmpty() || image.blocks.first().number != 0) {
        return Error::invalidData(QCoreApplication::translate(
            "cambench::comm", "the EEPROM image does not start with block 0000; nothing was sent"));
    }
    const int total = int(image.blocks.size()) + 1;  // + the empty end block
    std::optional<TransferFailure> failure;
    for (int attempt = 1; attempt <= kTransferAttempts; ++attempt) {
        failure = transfer(m_link, image, progress);
        if (!failure) {
            if (progress) progress(total, total);
            return success();
        }
        if (!failure->duplicate) break;
    }
    QString state;
    if (failure->index == 0) {
        state = QCoreApplication::translate(
            "cambench::comm", "The device may already be ERASED (block 0000 starts the erase).");
    } else if (failure->index < total - 1) {
        state = QCoreApplication::translate(
                    "cambench::comm",
                    "The device is now ERASED: it holds only the blocks before %1 "
                    "and does not run.")
                    .arg(hex4(failure->number));
    } else {
        state =
            QCoreApplication::translate("cambench::comm",
                                        "The device holds every block but did not confirm that it "
                                        "started.");
    }
    return inContext(QCoreApplication::translate(
                         "cambench::comm",
                         "restore failed at EEPROM block %1 of %2 (!EE%3). %4 Running the same "
                         "restore again is safe: it starts by erasing the device. Cause")
                         .arg(failure->index + 1)
                         .arg(total)
                         .arg(hex4(failure->number), state),
                     failure->error);
}

}  // namespace cambench::comm
