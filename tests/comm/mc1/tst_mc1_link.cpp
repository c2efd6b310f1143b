// Issue 14: MC-1 telegrams through the real request engine and the
// in-process transport to the simulated controller's line: answers,
// refusals, and which telegrams are repeated after a lost answer.
#include "comm/mc1/mc1_backend.h"
#include "comm/mc1/mc1_link.h"
#include "comm/sim/mc1/sim_mc1_line.h"
#include "comm/sim/sim_transport.h"

#include <QTest>

using namespace cambench;
using namespace cambench::comm;

namespace {

// The controller's line, losing its next `lose` answers (they were
// executed; only the answer is gone).
class LossyLine : public SimEndpoint {
public:
    explicit LossyLine(Mc1Variant variant) : line(variant) {}
    QList<SimOutput> receive(QByteArrayView bytes, qint64 nowMs) override {
        QList<SimOutput> out = line.receive(bytes, nowMs);
        if (lose > 0 && !out.isEmpty()) {
            --lose;
            return {};
        }
        return out;
    }
    QList<SimOutput> poll(qint64 nowMs) override { return line.poll(nowMs); }
    qint64 nextTimerMs() const override { return line.nextTimerMs(); }
    QString protocolName() const override { return line.protocolName(); }
    SimMc1Line line;
    int lose = 0;
};

// A simulated controller of `variant` behind the engine, at its baud rate.
struct Bench {
    explicit Bench(Mc1Variant variant)
        : transport(std::make_unique<LossyLine>(variant), SimPacer(9600, false),
                    QStringLiteral("simulated MC-1")),
          backend(variant),
          engine(transport, backend, settings()),
          link(engine, variant) {
        (void)transport.open();
    }
    static EngineSettings settings() {
        EngineSettings s;
        s.line.baud = 9600;
        return s;
    }
    LossyLine& line() { return static_cast<LossyLine&>(transport.line()); }
    SimMc1Controller& device() { return line().line.controller(); }

    SimTransport transport;
    Mc1Backend backend;
    RequestEngine engine;
    Mc1Link link;
};

QByteArray le(qint64 value, int bytes) {
    return mc1LittleEndian(value, bytes);
}

}  // namespace

class TestMc1Link : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void variablesThroughTheEngine() {
        for (Mc1Variant variant : {Mc1Variant::Mc100V1, Mc1Variant::Mc200V2}) {
            Bench bench(variant);
            const Result<QByteArray> written =
                bench.link.exchange(Mc1Op::WriteVariable, le(12, 2) + le(-5, 3));
            QVERIFY2(written.ok(), qPrintable(written.error().message));
            QVERIFY(written->isEmpty());  // ACK
            const Result<QByteArray> read = bench.link.exchange(Mc1Op::ReadVariable, le(12, 2));
            QVERIFY2(read.ok(), qPrintable(read.error().message));
            QCOMPARE(read->size(), mc1VariableBits(variant) / 8);
            QCOMPARE(mc1FromLittleEndian(*read, true), qint64(-5));
        }
    }

    void refusalsAreSaid() {
        Bench bench(Mc1Variant::Mc200V2);
        // Two bits in one WRBIT: the controller NAKs.
        QByteArray twoBits;
        twoBits.append(char(0x22));
        twoBits.append(char(0x03));
        const Result<QByteArray> nak = bench.link.exchange(Mc1Op::WriteBitInternal, twoBits);
        QVERIFY(!nak.ok());
        QCOMPARE(nak.error().kind, ErrorKind::DeviceError);
        QVERIFY2(nak.error().message.contains(QLatin1String("NAK")),
                 qPrintable(nak.error().message));
        // A telegram the variant lacks never leaves the PC.
        Bench mc100(Mc1Variant::Mc100V1);
        const Result<QByteArray> none = mc100.link.exchange(Mc1Op::ProgramStart, {});
        QCOMPARE(none.error().kind, ErrorKind::Unsupported);
        QVERIFY(mc100.transport.isOpen());
    }

    void programAndAxis() {
        Bench bench(Mc1Variant::Mc200V2);
        QVERIFY(bench.link.exchange(Mc1Op::ProgramStart, {}).ok());
        QVERIFY(bench.device().running());
        const Result<QByteArray> status = bench.link.exchange(Mc1Op::ProgramStatus, {});
        QVERIFY(status.ok());
        QCOMPARE(quint8(status->at(0)) & 0x03, 0x03);  // present, running
        QByteArray stop;
        stop.append(char(1));
        stop.append(char(0x08));
        QVERIFY(bench.link.exchange(Mc1Op::AxisCommand, stop).ok());
        QVERIFY(!bench.link.lastMayHaveActedTwice());
    }

    void aLostAnswerIsRepeatedOnlyWhereThatIsSafe() {
        Bench bench(Mc1Variant::Mc200V2);
        // A read: asked again, answered.
        bench.device().setVariable(3, 42);
        bench.line().lose = 1;
        const Result<QByteArray> read = bench.link.exchange(Mc1Op::ReadVariable, le(3, 2));
        QVERIFY2(read.ok(), qPrintable(read.error().message));
        QCOMPARE(mc1FromLittleEndian(*read, true), qint64(42));

        // A relative move whose answer is lost: sent once, never again (a
        // repeat would move the axis twice); the caller hears it failed.
        QByteArray relative;
        relative.append(char(1));
        relative.append(char(0x04));
        bench.line().lose = 1;
        const Result<QByteArray> moved =
            bench.link.exchange(Mc1Op::AxisDataCommand, relative + le(100, 4));
        QVERIFY(!moved.ok());
        QCOMPARE(bench.engine.lastAttempts(), 1);
        QTRY_VERIFY(!bench.device().axisMoving(1, 10000));
        QCOMPARE(bench.device().axisPosition(1, 10000), 100);  // moved once, by 100

        // A stop whose answer is lost: repeated, it leaves the axis stopped.
        QByteArray stop;
        stop.append(char(1));
        stop.append(char(0x09));
        bench.line().lose = 1;
        QVERIFY(bench.link.exchange(Mc1Op::AxisCommand, stop).ok());
        QCOMPARE(bench.engine.lastAttempts(), 2);
    }
};

QTEST_GUILESS_MAIN(TestMc1Link)
#include "tst_mc1_link.moc"
