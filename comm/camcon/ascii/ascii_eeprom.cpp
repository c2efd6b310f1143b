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
constexpr qint32 kNoTransfer = -46;       // "data reception incomplete": no transfer is open

// A restore that lost its place starts over, a bounded number of times.
constexpr int kTransferAttempts = 5;

QString hex4(int number) {
    return QStringLiteral("%1").arg(number, 4, 16, QChar(u'0')).toUpper();
}

// Standard framing has no block numbers, and a block that reached the device
// must not be sent again: the order lock answers -43 and ends the transfer.
// A damaged answer still proves that the device took the block (it answers
// after storing it). A block that drew no answer at all may have been
// stored (its reply was lost, or came late) or not (the request was hit and
// ignored): the transfer guesses, and the device's order lock catches a
// wrong guess at the next block (-43 or -46) - never a wrong image. The
// next pass then takes the guess that would have been right.
enum class SilenceMeans {
    Stored,       // go on with the next block
    NotReceived,  // send the block again
};

// Silent blocks in a row after which the line itself is in question: the
// next one is sent again until it is answered or the link gives up.
constexpr int kSilentRun = 3;

// How one block's answer was known.
enum class Fate {
    Confirmed,         // :EEOK (or an error)
    AssumedFromReply,  // a damaged answer: taken as stored
    AssumedSilent,     // no answer, guessed stored
    ResentSilent,      // no answer, guessed not received and sent again
};

struct TransferFailure {
    int index;   // position in the transfer, 0 = block 0000
    int number;  // block number sent
    Error error;
    // The device ended the transfer (-43, -46) right after a block whose
    // fate was assumed: a new pass from block 0000 (which erases first) is
    // the way on, with `rightGuess` when a silent block was guessed wrong.
    bool placeLost;
    std::optional<SilenceMeans> rightGuess;
};

// Sends one !EE block. In Multiuser framing the link's retries are safe: a
// repeated block number makes the device repeat its answer. In Standard
// framing the catalogue sends !EE once (RetryPolicy::Never), and silence
// means what `silence` says; without it (block 0000 and the end block,
// which the link has already probed for their long working time) silence
// is a failure.
Result<Fields> sendBlock(AsciiLink& link, const Fields& fields, std::optional<SilenceMeans> silence,
                         Fate& fate) {
    fate = Fate::Confirmed;
    Result<Fields> reply = link.call('!', "EE", fields);
    if (reply || link.settings().framing == Framing::Multiuser ||
        reply.error().kind != ErrorKind::Communication) {
        return reply;
    }
    if (link.lastCallHeardDevice()) {
        fate = Fate::AssumedFromReply;
        return Fields{};
    }
    if (!silence) return reply;
    if (*silence == SilenceMeans::Stored) {
        fate = Fate::AssumedSilent;
        return Fields{};
    }
    fate = Fate::ResentSilent;
    for (int attempt = 0; attempt < link.settings().retries; ++attempt) {
        reply = link.call('!', "EE", fields);
        if (reply || reply.error().kind != ErrorKind::Communication) return reply;
        if (link.lastCallHeardDevice()) return Fields{};
    }
    return reply;
}

// One pass: !EE0000 (erases), every block in ascending order, then the
// empty block that starts the device. `endFate` tells how the end block's
// answer was known.
std::optional<TransferFailure> transfer(AsciiLink& link, const EepromImage& image,
                                        SilenceMeans guess, const ProgressFn& progress,
                                        Fate& endFate) {
    const int total = int(image.blocks.size()) + 1;
    Fate previous = Fate::Confirmed;
    int silentRun = 0;
    for (int i = 0; i < total; ++i) {
        if (progress) progress(i, total);
        const bool endBlock = i == total - 1;
        const int number = endBlock ? image.blocks.last().number + 1 : image.blocks.at(i).number;
        Fields fields{{"block", qint64(number)}};
        fields.setBytes("data", endBlock ? QByteArray() : image.blocks.at(i).data);
        // Block 0000 (erases) and the end block (starts the device) take
        // long: the link gives them the long timeout class and its probe.
        std::optional<SilenceMeans> silence;
        if (i > 0 && !endBlock)
            silence = silentRun + 1 >= kSilentRun ? SilenceMeans::NotReceived : guess;
        Fate fate = Fate::Confirmed;
        const Result<Fields> reply = sendBlock(link, fields, silence, fate);
        if (reply) {
            const bool silent = fate == Fate::AssumedSilent || fate == Fate::ResentSilent;
            silentRun = silent ? silentRun + 1 : 0;
            previous = fate;
            endFate = fate;
            continue;
        }
        const bool placeLost = i > 0 && reply.error().kind == ErrorKind::DeviceError &&
                               (reply.error().deviceCode == kWrongBlockOrder ||
                                reply.error().deviceCode == kNoTransfer) &&
                               (fate == Fate::ResentSilent || previous != Fate::Confirmed);
        std::optional<SilenceMeans> rightGuess;
        if (placeLost && fate == Fate::ResentSilent) {
            rightGuess = SilenceMeans::Stored;  // the first copy had been stored
        } else if (placeLost && previous == Fate::AssumedSilent) {
            rightGuess = SilenceMeans::NotReceived;  // the silent block had not arrived
        }
        return TransferFailure{i, number, reply.error(), placeLost, rightGuess};
    }
    return std::nullopt;
}

// A restore whose end block drew no clear answer: did the device start?
Status confirmStarted(AsciiCamCon& device, AsciiLink& link, const EepromImage& image) {
    // The end block's answer was lost or damaged. Sent again, it either
    // starts a device that never got it, or draws "no transfer open" from
    // one that closed the transfer with the first copy - by starting, or by
    // failing to start. Reading the EEPROM back tells which.
    const int number = image.blocks.last().number + 1;
    Fields fields{{"block", qint64(number)}};
    fields.setBytes("data", QByteArray());
    const Result<Fields> again = link.call('!', "EE", fields);
    if (again) return success();
    const auto failed = [&](const QString& why, const Error& cause) {
        return inContext(
            QCoreApplication::translate("cambench::comm",
                                        "restore: the device took every block but did not "
                                        "confirm that it started (!EE%1): %2. Run the same "
                                        "restore again. Cause")
                .arg(hex4(number), why),
            cause);
    };
    if (again.error().kind != ErrorKind::DeviceError || again.error().deviceCode != kNoTransfer)
        return failed(
            QCoreApplication::translate("cambench::comm", "the end block, sent again, failed"),
            again.error());
    const Result<EepromImage> readBack = device.backup();
    if (!readBack)
        return failed(
            QCoreApplication::translate("cambench::comm", "reading the EEPROM back failed"),
            readBack.error());
    if (readBack->blocks != image.blocks) {
        return failed(
            QCoreApplication::translate("cambench::comm", "its EEPROM differs from the image"),
            Error::communication(QCoreApplication::translate("cambench::comm",
                                                             "%1 blocks read back, %2 in the image")
                                     .arg(readBack->blocks.size())
                                     .arg(image.blocks.size())));
    }
    return success();
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
    SilenceMeans guess = SilenceMeans::Stored;
    for (int attempt = 1; attempt <= kTransferAttempts; ++attempt) {
        Fate endFate = Fate::Confirmed;
        failure = transfer(m_link, image, guess, progress, endFate);
        if (!failure) {
            const Status started =
                endFate == Fate::Confirmed ? success() : confirmStarted(*this, m_link, image);
            if (!started) return started;
            if (progress) progress(total, total);
            return success();
        }
        if (!failure->placeLost) break;
        if (failure->rightGuess) guess = *failure->rightGuess;
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
