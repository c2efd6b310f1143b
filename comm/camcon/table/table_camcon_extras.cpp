// What only the table interface reaches: analogue cams (areas 241..254), the
// programming program (area 201 words 70..73), the EEPROM lock (area 205).
#include "cam_track_words.h"
#include "table_camcon.h"
#include "table_map.h"
#include "table_word_block.h"

#include "comm/device/error_context.h"

#include <QCoreApplication>

namespace cambench::comm::table {

// Area 203 word 38 (manual 3.4): a device without analogue outputs answers
// RK512 error 20 for areas 241..254, so their number is read first.
Result<int> TableCamCon::readAnalogueOutputCount() {
    const Result<qint32> count = m_link.readWord(kSystemArea, tableWord(u"system.analog_outputs"));
    if (!count)
        return inContext(
            QCoreApplication::translate("cambench::comm", "reading the number of analogue outputs"),
            count.error());
    if (*count < 0 || *count > kAnalogueOutputs) {
        return Error::invalidData(
            QCoreApplication::translate(
                "cambench::comm",
                "The device says it has %1 analogue outputs (area 203 word 38); the "
                "manual allows 0..%2.")
                .arg(*count)
                .arg(kAnalogueOutputs));
    }
    return int(*count);
}

Result<AnalogueCamTrack> TableCamCon::readAnalogueCams(int analogueOutput) {
    const QString what = QCoreApplication::translate(
                             "cambench::comm", "reading the analogue cams of analogue output %1")
                             .arg(analogueOutput);
    if (analogueOutput < 1 || analogueOutput > kAnalogueOutputs) {
        return Error::usage(
            QCoreApplication::translate("cambench::comm", "%1: analogue outputs are 1..%2")
                .arg(what)
                .arg(kAnalogueOutputs));
    }
    const Result<QList<qint32>> words =
        readPairWords(kFirstAnalogCamArea + analogueOutput - 1, u"analog_cam.count",
                      QCoreApplication::translate("cambench::comm", "base points"));
    if (!words) return inContext(what, words.error());
    AnalogueCamTrack track;
    track.output = analogueOutput;
    for (qsizetype i = 0; i + 1 < words->size(); i += 2) {
        if (words->at(i) == kEmptyCamWord) continue;
        track.points.append(AnaloguePoint{words->at(i), words->at(i + 1)});
    }
    return track;
}

Status TableCamCon::writeAnalogueCams(const AnalogueCamTrack& track) {
    const QString what = QCoreApplication::translate(
                             "cambench::comm", "writing the analogue cams of analogue output %1")
                             .arg(track.output);
    if (track.output < 1 || track.output > kAnalogueOutputs) {
        return Error::usage(
            QCoreApplication::translate("cambench::comm", "%1: analogue outputs are 1..%2")
                .arg(what)
                .arg(kAnalogueOutputs));
    }
    if (track.points.size() > writablePairs()) {
        return Error::usage(QCoreApplication::translate(
                                "cambench::comm", "%1: %2 base points, but over %3 at most %4 fit")
                                .arg(what)
                                .arg(track.points.size())
                                .arg(QLatin1String(rk512VariantInfo(m_link.variant()).name))
                                .arg(writablePairs()));
    }
    // The cam rules of manual 3.1 read for base points too (provisional,
    // README): from place 1 with at least two pairs the whole set is replaced.
    QList<qint32> words;
    for (const AnaloguePoint& point : track.points) words << point.position << point.value;
    while (words.size() < 4) words.append(kRewritePaddingWord);
    const Status written = writePairWords(
        kFirstAnalogCamArea + track.output - 1, words,
        QCoreApplication::translate("cambench::comm", "base points"), int(track.points.size()));
    if (!written) return inContext(what, written.error());
    return success();
}

Result<ProgrammingProgram> TableCamCon::readProgrammingProgram() {
    const Result<WordBlock> block = WordBlock::read(
        m_link, kStatusArea, u"status.programming_program", u"status.programming_switch_value");
    if (!block)
        return inContext(
            QCoreApplication::translate("cambench::comm", "reading the programming program"),
            block.error());
    ProgrammingProgram programming;
    programming.program = block->at(u"status.programming_program");
    programming.selectMode = block->at(u"status.programming_select_mode");
    programming.switchValue = block->at(u"status.programming_switch_value");
    return programming;
}

Status TableCamCon::writeProgrammingProgram(const ProgrammingProgram& programming) {
    const QString what =
        QCoreApplication::translate("cambench::comm", "writing the programming program");
    if (const Status selected = selectProgrammingProgram(programming.program); !selected)
        return inContext(what, selected.error());
    const Status written =
        m_link.writeWords(kStatusArea, tableWord(u"status.programming_select_mode"),
                          {programming.selectMode, programming.switchValue});
    if (!written) return inContext(what, written.error());
    return success();
}

Result<bool> TableCamCon::readEepromLock() {
    const Result<qint32> lock = m_link.readWord(kConfigArea, tableWord(u"config.eeprom_lock"));
    if (!lock)
        return inContext(QCoreApplication::translate("cambench::comm", "reading the EEPROM lock"),
                         lock.error());
    return *lock != 0;
}

Status TableCamCon::writeEepromLock(bool locked) {
    const Status written =
        m_link.writeWord(kConfigArea, tableWord(u"config.eeprom_lock"), locked ? 1 : 0);
    if (!written) {
        return inContext(
            locked ? QCoreApplication::translate("cambench::comm", "locking the EEPROM")
                   : QCoreApplication::translate("cambench::comm", "unlocking the EEPROM"),
            written.error());
    }
    return success();
}

}  // namespace cambench::comm::table
