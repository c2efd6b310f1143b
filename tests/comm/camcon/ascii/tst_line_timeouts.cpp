// The per-attempt timeouts every command of the CamCon ASCII catalogue gets
// from the line: enough for its longest reply at the baud rate plus the
// turnaround, short enough that a lost reply costs little, and the long
// class (with its probe) where the device works first.
#include "../../engine/scripted_line.h"

#include "comm/camcon/ascii/ascii_link.h"

#include <QtTest>

using namespace cambench;
using namespace cambench::comm;
using namespace cambench::comm::test;

namespace {

// The largest frame the decoder takes: no reply can be longer.
constexpr int kMaxFrameBytes = 1024;

LineTiming lineAt(int baud) {
    LineTiming line;
    line.baud = baud;
    return line;
}

// A request as long as it gets: EEPROM blocks of 90 bytes that all need an
// ESC, the rest with its default fields.
Fields longestFields(const CommandSpec& spec) {
    Fields fields;
    if (spec.kind == kCommand && qstrcmp(spec.name, "EE") == 0) {
        fields.set("block", 5);
        fields.setBytes("data", QByteArray(1, '\xF0') + QByteArray(89, kCr));
    }
    return fields;
}

}  // namespace

class TestLineTimeouts : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void everyCommandGetsItsReplyTimePlusTheTurnaround_data();
    void everyCommandGetsItsReplyTimePlusTheTurnaround();
    void eraseAndStartBlocksAreLongAndProbed();
};

void TestLineTimeouts::everyCommandGetsItsReplyTimePlusTheTurnaround_data() {
    QTest::addColumn<int>("framing");
    QTest::newRow("Standard") << int(Framing::Standard);
    QTest::newRow("Multiuser") << int(Framing::Multiuser);
}

void TestLineTimeouts::everyCommandGetsItsReplyTimePlusTheTurnaround() {
    QFETCH(int, framing);
    VirtualClock clock;
    ScriptedLine line(clock, {});
    AsciiSettings settings;
    settings.framing = Framing(framing);
    settings.syncBlockNumbers = false;
    AsciiLink slow(line, settings, lineAt(9600));
    AsciiLink fast(line, settings, lineAt(38400));
    const LineTiming timing = lineAt(9600);
    for (const CommandSpec& spec : commandCatalogue()) {
        const QString what = QString(QChar(spec.kind)) + QLatin1String(spec.name);
        const Fields fields = longestFields(spec);
        const int atSlow = slow.attemptTimeoutMs(spec, fields);
        const int atFast = fast.attemptTimeoutMs(spec, fields);
        QVERIFY2(atSlow > 0, qPrintable(what));
        if (spec.timeout == TimeoutClass::Long ||
            (spec.kind == kCommand && qstrcmp(spec.name, "EE") == 0)) {
            continue;  // the next test
        }
        // The request and a reply of at least the name and an error code
        // cross the line, then the device turns around...
        const int shortest = timing.turnaroundMs + timing.wireMs(int(qstrlen(spec.name)) + 2 * 8);
        QVERIFY2(atSlow >= shortest, qPrintable(QStringLiteral("%1: %2 ms").arg(what).arg(atSlow)));
        // ...and no more than the largest frame in each direction.
        QVERIFY2(atSlow <= timing.turnaroundMs + timing.wireMs(2 * kMaxFrameBytes),
                 qPrintable(QStringLiteral("%1: %2 ms").arg(what).arg(atSlow)));
        // A faster line waits less for the same bytes.
        QVERIFY2(atFast < atSlow, qPrintable(what));
        QVERIFY2(atFast >= timing.turnaroundMs, qPrintable(what));
    }
}

void TestLineTimeouts::eraseAndStartBlocksAreLongAndProbed() {
    VirtualClock clock;
    ScriptedLine line(clock, {});
    const CommandSpec* eeprom = findCommand(kCommand, "EE");
    const CommandSpec* clear = findCommand(kCommand, "CA");
    QVERIFY(eeprom && clear);
    const LineTiming timing = lineAt(9600);
    Fields erase;
    erase.set("block", 0).setBytes("data", QByteArray(128, '\x01'));
    Fields start;
    start.set("block", 0x30).setBytes("data", QByteArray());
    for (const Framing framing : {Framing::Standard, Framing::Multiuser}) {
        AsciiSettings settings;
        settings.framing = framing;
        AsciiLink link(line, settings, timing);
        const int block = link.attemptTimeoutMs(*eeprom, longestFields(*eeprom));
        // Both probed (Standard) or repeated (Multiuser) after a few seconds
        // of silence: never 150 s without asking the device.
        for (const int longMs :
             {link.attemptTimeoutMs(*eeprom, erase), link.attemptTimeoutMs(*eeprom, start),
              link.attemptTimeoutMs(*clear)}) {
            QVERIFY(longMs >= timing.probeAfterMs);
            QVERIFY(longMs < timing.probeAfterMs + 1000);
        }
        // An ordinary block needs its 181 bytes at 9600 baud, not seconds.
        QVERIFY(block >= timing.turnaroundMs + timing.wireMs(180));
        QVERIFY(block < timing.probeAfterMs);
    }
}

QTEST_GUILESS_MAIN(TestLineTimeouts)
#include "tst_line_timeouts.moc"
