// Issue 16: the Cam-BUS as a whole, on a virtual clock: simulated CamCons
// and a display on the simulated wire, the PC as one more station, every
// byte through the same state machine. Joining a bus that has a master and
// one where the PC must become master, requests to two devices while the
// display polls, the block bit's repeat check, a full receive queue, a
// device that leaves and rejoins, a second initialisation phase.
#include "comm/camcon/cambus/cambus_payload.h"
#include "comm/camcon/cambus/cambus_station.h"
#include "comm/sim/camcon/cambus/sim_cambus_line.h"
#include "comm/sim/camcon/sim_demo.h"

#include <QTest>

using namespace cambench;
using namespace cambench::comm;

namespace {

// The bus and the PC, run in steps of 1 ms of virtual time.
struct VirtualBus {
    explicit VirtualBus(QList<int> devices, int display = -1, int pcNumber = 63,
                        SimCamBusFaults faults = {}) {
        std::vector<std::unique_ptr<SimDevice>> made;
        for (int number : devices) {
            auto device = std::make_unique<SimDevice>(SimProfile{}, number);
            loadDemoState(*device);
            made.push_back(std::move(device));
        }
        SimCamBusLine::Setup setup;
        if (display >= 0) setup.displays = {display};
        setup.faults = faults;
        line = std::make_unique<SimCamBusLine>(std::move(made), setup, 0);
        pcConfig.number = pcNumber;
        pcConfig.joinBeforeFirstBlock = true;
    }

    // The PC opens the port now.
    void plugPc() { pc = std::make_unique<CamBusStation>(pcConfig, now); }

    void run(qint64 ms) {
        const qint64 end = now + ms;
        for (; now < end; now = nextStep(end)) {
            QByteArray heard;
            for (const SimOutput& out : line->poll(now)) heard += out.bytes;
            if (!pc) continue;
            if (!heard.isEmpty()) pc->feed(heard, now);
            pc->poll(now);
            for (int i = 0; i < 4; ++i) {  // the PC's answer and what it sets off
                const QByteArray out = pc->takeOutput();
                if (out.isEmpty()) break;
                QByteArray back;
                for (const SimOutput& o : line->receive(out, now)) back += o.bytes;
                if (!back.isEmpty()) pc->feed(back, now);
            }
            for (const CamBusStation::Received& r : pc->takeReceived()) received << r;
            for (const CamBusStation::Delivery& d : pc->takeDeliveries()) deliveries << d;
        }
    }

    // The next moment anything is due (virtual time jumps over quiet stretches).
    qint64 nextStep(qint64 end) const {
        qint64 next = end;
        for (qint64 timer : {line->nextTimerMs(), pc ? pc->nextTimerMs() : qint64(-1)})
            if (timer >= 0) next = std::min(next, std::max(timer, now + 1));
        return next;
    }

    // Sends `request` to `device` and runs until its reply (or `limitMs`).
    QByteArray ask(int device, const QByteArray& request, qint64 limitMs = 6000) {
        received.clear();
        pc->send(device, camBusPayload(request.at(0), request.mid(1)));
        for (qint64 waited = 0; waited < limitMs; waited += 5) {
            run(5);
            for (const CamBusStation::Received& r : received) {
                if (r.source != device) continue;
                const Result<Frame> frame = parseCamBusPayload(r.data);
                if (frame) return frame->lead + frame->body;
            }
        }
        return {};
    }

    std::unique_ptr<SimCamBusLine> line;
    CamBusStationConfig pcConfig;
    std::unique_ptr<CamBusStation> pc;
    QList<CamBusStation::Received> received;
    QList<CamBusStation::Delivery> deliveries;
    qint64 now = 0;
};

}  // namespace

class TestCamBusBus : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void theBusFormsWithoutThePc() {
        VirtualBus bus({3, 7}, 12);
        bus.run(5000);
        // Nobody polled anybody for 1250 ms: an initialisation phase; the
        // lowest number won and passes the token to 3, 7 and 12.
        const CamBusView& view = bus.line->camCon(3)->station().view();
        QCOMPARE(view.users.keys(), QList<int>({3, 7, 12}));
        QCOMPARE(view.master, 3);
        QVERIFY(bus.line->camCon(3)->station().isMaster());
        QVERIFY(!bus.line->camCon(7)->station().isMaster());
        QVERIFY(bus.line->display()->answers() > 20);
    }

    void thePcJoinsABusThatHasAMaster() {
        VirtualBus bus({3, 7}, 12);
        bus.run(6000);  // the bus is past its search, 3 is master
        bus.plugPc();
        const qint64 pluggedAt = bus.now;
        QCOMPARE(bus.ask(3, "?GNR"), QByteArray(":GNR03"));
        QVERIFY(bus.pc->joined());
        QCOMPARE(bus.pc->view().initPhases, 1);  // the PC broke in
        QVERIFY(!bus.pc->isMaster());
        QCOMPARE(bus.pc->view().users.keys(), QList<int>({3, 7, 12, 63}));
        QCOMPARE(bus.pc->view().master, 3);
        // Without waiting out 1250 ms: one round without the PC was enough (CB1).
        qInfo() << "joined and answered after" << bus.now - pluggedAt << "ms";
        QVERIFY(bus.now - pluggedAt < 1250 + 2500);
    }

    void thePcBecomesMasterWhenItHasTheLowestNumber() {
        VirtualBus bus({3, 7}, 12, 1);
        bus.run(6000);  // the bus is past its search, 3 is master
        bus.plugPc();
        QCOMPARE(bus.ask(7, "?GNR"), QByteArray(":GNR07"));
        QVERIFY(bus.pc->isMaster());
        QVERIFY(!bus.line->camCon(3)->station().isMaster());
        QCOMPARE(bus.pc->view().users.keys(), QList<int>({1, 3, 7, 12}));
        // The PC passes the token: the display goes on being answered.
        const int before = bus.line->display()->answers();
        bus.line->display()->resetPauses(bus.now);
        bus.run(3000);
        QVERIFY(bus.line->display()->answers() > before + 20);
        QVERIFY(bus.line->display()->longestPauseMs() < 1500);
    }

    void thePcOnADeadBusIsMasterAlone() {
        VirtualBus bus({3});
        bus.line->camCon(3)->station().setSilent(true);
        bus.plugPc();
        bus.pc->send(5, camBusPayload('?', "GNR"));
        bus.run(6000);
        QVERIFY(bus.pc->isMaster());
        QCOMPARE(bus.pc->view().users.keys(), QList<int>({63}));
        // Nobody answers TO 5: given up after 3 silent turns, never sent.
        QCOMPARE(bus.deliveries.size(), 1);
        QCOMPARE(bus.deliveries.first().result, CamBusStation::Delivery::NotTaken);
    }

    void requestsToTwoDevicesWhileTheDisplayPolls() {
        VirtualBus bus({3, 7}, 12);
        bus.run(4000);
        bus.plugPc();
        QCOMPARE(bus.ask(3, "?GNR"), QByteArray(":GNR03"));  // joined
        bus.line->display()->resetPauses(bus.now);
        const int displayBefore = bus.line->display()->answers();
        for (int i = 0; i < 40; ++i) {
            const int device = i % 2 ? 7 : 3;
            const QByteArray got = bus.ask(device, "?GNR");
            QCOMPARE(got, QByteArray(":GNR") + QByteArray::number(device).rightJustified(2, '0'));
        }
        QVERIFY(bus.line->display()->answers() > displayBefore + 20);
        qInfo() << "display's longest pause while the PC worked:"
                << bus.line->display()->longestPauseMs() << "ms";
        QVERIFY(bus.line->display()->longestPauseMs() < 1500);
        // Each request executed once.
        QCOMPARE(bus.line->device(7)->executions(), 20);
    }

    // Issue 39: a block longer than T on the wire (38400 baud: 10 ms is 38
    // bytes) has no gap in it; every listener hears its bytes as they cross
    // and waits T from the last one, not from its start. Before, the
    // simulated users heard a block only once its last byte had crossed, so
    // the master took the turn for over and passed the token across it.
    void blocksLongerThanTCrossTheWire() {
        VirtualBus bus({3, 7}, 12);
        bus.run(4000);
        bus.plugPc();
        QCOMPARE(bus.ask(3, "?GNR"), QByteArray(":GNR03"));
        // A request of 200 characters to the master (52 ms on the wire): the
        // device takes it and answers that it does not know it.
        bus.deliveries.clear();
        const QByteArray unknown = "?ZZ" + QByteArray(197, 'A');
        QVERIFY(bus.ask(3, unknown).startsWith(":Z"));
        QCOMPARE(bus.deliveries.size(), 1);
        QCOMPARE(bus.deliveries.first().result, CamBusStation::Delivery::Delivered);
        // A long reply from 7 while 3, the master, listens: an EEPROM block.
        const QByteArray block = bus.ask(7, "?EE0000");
        QVERIFY2(block.size() > 100, block.toHex().constData());
        QVERIFY(block.startsWith(":EE0000"));
        // Nobody broke in meanwhile: one initialisation phase, the PC's own.
        QCOMPARE(bus.pc->view().initPhases, 1);
    }

    // Issue 39: a PC that reads the line late (a busy computer) gets the byte
    // it should answer together with what the others sent after T went by.
    // Answering then would put its bytes into the next turn (the master's
    // "user 3 answered its TO with 87"): it lets the turn go, counts it, and
    // its block goes whole at a later token.
    void aLatePcLetsTheTurnGoInsteadOfAnsweringIntoTheNext() {
        CamBusStationConfig config;
        config.number = 63;
        config.joinBeforeFirstBlock = true;
        CamBusStation pc(config, 0);
        pc.feed(QByteArray::fromHex("ffff"), 0);  // C0+63: joined
        QCOMPARE(pc.takeOutput(), QByteArray::fromHex("7f"));
        pc.send(3, camBusPayload('?', "GNR"));
        // Its token, and after it (the PC was silent for T) 3's token and answer.
        pc.feed(camBusToken(63) + camBusToken(3) + QByteArray::fromHex("83"), 20);
        QCOMPARE(pc.takeOutput(), QByteArray());
        QCOMPARE(pc.view().lateAnswers, 1);
        // In time for its token, late for 3's room answer: no block.
        pc.feed(camBusToken(63), 40);
        QCOMPARE(pc.takeOutput(), QByteArray::fromHex("7f03"));
        pc.feed(QByteArray::fromHex("43") + camBusToken(7) + QByteArray::fromHex("87"), 60);
        QCOMPARE(pc.takeOutput(), QByteArray());
        QCOMPARE(pc.view().lateAnswers, 2);
        QVERIFY(pc.takeDeliveries().isEmpty());
        QVERIFY(pc.hasQueued());
        // Its answer to the token came too late (read in time, but the
        // master had gone on): the next token instead of 3's room answer.
        // Three times: no failure blamed on 3, the block stays.
        for (int i = 0; i < 3; ++i) {
            pc.feed(camBusToken(63), 62 + 2 * i);
            QCOMPARE(pc.takeOutput(), QByteArray::fromHex("7f03"));
            pc.feed(camBusToken(7) + QByteArray::fromHex("87"), 63 + 2 * i);
        }
        QVERIFY(pc.takeDeliveries().isEmpty());
        QVERIFY(pc.hasQueued());
        QCOMPARE(pc.view().lateAnswers, 5);
        // In time: the block goes as in the worked example.
        pc.feed(camBusToken(63), 80);
        QCOMPARE(pc.takeOutput(), QByteArray::fromHex("7f03"));
        pc.feed(QByteArray::fromHex("43"), 81);
        QCOMPARE(pc.takeOutput(), QByteArray::fromHex("063f474e52443901a9"));
        pc.feed(QByteArray::fromHex("83"), 82);
        QCOMPARE(pc.takeDeliveries().size(), 1);
        // A reply heard late is taken but not acknowledged; its repeat is
        // acknowledged and not taken again.
        const QByteArray reply = QByteArray::fromHex("a5370303433f");
        const QByteArray block = QByteArray::fromHex("083a474e52303337420205");
        pc.feed(reply, 100);
        QCOMPARE(pc.takeOutput(), QByteArray::fromHex("7f"));
        pc.feed(block + camBusToken(7), 101);
        QCOMPARE(pc.takeOutput(), QByteArray());
        QCOMPARE(pc.takeReceived().size(), 1);
        pc.feed(reply, 120);
        QCOMPARE(pc.takeOutput(), QByteArray::fromHex("7f"));
        pc.feed(block, 121);
        QCOMPARE(pc.takeOutput(), QByteArray::fromHex("bf"));
        QVERIFY(pc.takeReceived().isEmpty());
        QCOMPARE(pc.view().lateAnswers, 6);
    }

    void aRepeatedBlockIsAcknowledgedButNotTakenAgain() {
        // The PC 63 hears CamCon 3's token and its block to the PC, sent
        // twice with the same block bit (the PC's acknowledgement was lost).
        CamBusStationConfig config;
        config.number = 63;
        CamBusStation pc(config, 0);
        const QByteArray block = *encodeCamBusBlock({QByteArray(":GNR037B"), false});
        for (int i = 0; i < 2; ++i) {
            pc.feed(camBusToken(3), 10 + i);
            pc.feed(QByteArray::fromHex("433f"), 10 + i);          // 3 has a block, TO 63
            QCOMPARE(pc.takeOutput(), QByteArray::fromHex("7f"));  // room
            pc.feed(block, 10 + i);
            QCOMPARE(pc.takeOutput(), QByteArray::fromHex("bf"));  // received
        }
        const QList<CamBusStation::Received> got = pc.takeReceived();
        QCOMPARE(got.size(), 1);
        QCOMPARE(got.first().data, QByteArray(":GNR037B"));
        // The next block (bit toggled) is new.
        pc.feed(camBusToken(3), 20);
        pc.feed(QByteArray::fromHex("433f"), 20);
        pc.feed(*encodeCamBusBlock({QByteArray(":GNR037B"), true}), 20);
        QCOMPARE(pc.takeReceived().size(), 1);
    }

    void theWorkedExampleFromThePcsSide() {
        // docs/protocols/cambus.md: PC 63 asks CamCon 3 (master) ?GNR, byte for byte.
        CamBusStationConfig config;
        config.number = 63;
        config.joinBeforeFirstBlock = true;
        CamBusStation pc(config, 0);
        pc.send(3, camBusPayload('?', "GNR"));
        pc.feed(camBusToken(63), 5);
        // Not joined since opening: the transmitter answers empty, and the
        // PC breaks in (64 breaks) before its first block.
        const QByteArray out = pc.takeOutput();
        QCOMPARE(out.left(1), QByteArray::fromHex("bf"));
        QCOMPARE(out.mid(1), QByteArray::fromHex("ff0000").repeated(64));
        // The RID search reaches 63: answered, joined.
        // (C0+63 is FF, doubled on the line: P12.)
        pc.feed(QByteArray::fromHex("ffff"), 100);
        QCOMPARE(pc.takeOutput(), QByteArray::fromHex("7f"));
        QVERIFY(pc.joined());
        pc.feed(camBusToken(63), 110);
        QCOMPARE(pc.takeOutput(), QByteArray::fromHex("7f03"));  // a block, TO 3
        pc.feed(QByteArray::fromHex("43"), 111);                 // 3 has room
        QCOMPARE(pc.takeOutput(), QByteArray::fromHex("063f474e52443901a9"));
        pc.feed(QByteArray::fromHex("83"), 112);  // received
        const QList<CamBusStation::Delivery> done = pc.takeDeliveries();
        QCOMPARE(done.size(), 1);
        QCOMPARE(done.first().result, CamBusStation::Delivery::Delivered);
        // The reply: A5 37 03 03, 43 3F, 7F (the PC has room), block, BF.
        pc.feed(QByteArray::fromHex("a5370303433f"), 130);
        QCOMPARE(pc.takeOutput(), QByteArray::fromHex("7f"));
        pc.feed(QByteArray::fromHex("083a474e52303337420205"), 131);
        QCOMPARE(pc.takeOutput(), QByteArray::fromHex("bf"));
        QCOMPARE(pc.takeReceived().first().data, QByteArray(":GNR037B"));
    }

    void aFullQueueDelaysButDoesNotDrop() {
        VirtualBus bus({3}, 12);
        bus.run(4000);
        bus.plugPc();
        QCOMPARE(bus.ask(3, "?GNR"), QByteArray(":GNR03"));
        bus.deliveries.clear();
        bool full = true;
        bus.line->camCon(3)->station().setRoomCheck([&full] { return !full; });
        bus.pc->send(3, camBusPayload('?', "GNR"));
        bus.run(1000);  // 80+3 to every TO: no failure, the block waits
        QVERIFY(bus.deliveries.isEmpty());
        QVERIFY(bus.pc->hasQueued());
        full = false;
        bus.received.clear();
        bus.run(500);
        QCOMPARE(bus.deliveries.size(), 1);
        QCOMPARE(bus.deliveries.first().result, CamBusStation::Delivery::Delivered);
        QCOMPARE(bus.received.size(), 1);
    }

    void aDeviceLeavesAndRejoins() {
        VirtualBus bus({3, 7}, 12);
        bus.run(4000);
        bus.plugPc();
        QCOMPARE(bus.ask(7, "?GNR"), QByteArray(":GNR07"));
        bus.line->camCon(7)->station().setSilent(true);
        bus.deliveries.clear();
        QCOMPARE(bus.ask(7, "?GNR", 2000), QByteArray());
        QCOMPARE(bus.deliveries.size(), 1);
        QCOMPARE(bus.deliveries.first().result, CamBusStation::Delivery::NotTaken);
        // 7 stays in the table (P4) but answers nothing; the others go on.
        QVERIFY(bus.pc->view().users.contains(7));
        QVERIFY(!bus.pc->view().users.value(7).answers);
        QCOMPARE(bus.ask(3, "?GNR"), QByteArray(":GNR03"));
        // A second initialisation phase (another user breaks in): 7 is out.
        bus.line->camCon(3)->station().breakIn(bus.now);
        bus.run(4000);
        QVERIFY(!bus.pc->view().users.contains(7));
        // 7 comes back, is not polled, breaks in after 1250 ms and is in again.
        bus.line->camCon(7)->station().setSilent(false);
        bus.run(6000);
        QVERIFY(bus.pc->view().users.contains(7));
        QCOMPARE(bus.ask(7, "?GNR"), QByteArray(":GNR07"));
    }

    void aBreakWhileABlockIsUnacknowledgedIsNotResent() {
        CamBusStationConfig config;
        config.number = 63;
        CamBusStation pc(config, 0);
        pc.feed(QByteArray::fromHex("ffff"), 0);  // C0+63: the RID search reaches the PC
        pc.takeOutput();
        pc.send(3, camBusPayload('!', "GNR05"));
        pc.feed(camBusToken(63), 10);
        pc.feed(QByteArray::fromHex("43"), 10);
        QVERIFY(!pc.takeOutput().isEmpty());         // the block left
        pc.feed(QByteArray::fromHex("ff0000"), 11);  // a break before 83
        const QList<CamBusStation::Delivery> done = pc.takeDeliveries();
        QCOMPARE(done.size(), 1);
        QCOMPARE(done.first().result, CamBusStation::Delivery::Uncertain);
        QVERIFY(!pc.hasQueued());
    }

    void damagedBlocksAndLostAcknowledgementsAtOnePercent() {
        SimCamBusFaults faults;
        faults.damageBlock = 0.01;
        faults.loseAck = 0.01;
        faults.seed = 7;
        VirtualBus bus({3, 7}, 12, 63, faults);
        bus.run(4000);
        bus.plugPc();
        int answered = 0;
        for (int i = 0; i < 200; ++i) {
            const int device = i % 2 ? 7 : 3;
            const QByteArray reply = bus.ask(device, "?GNR", 3000);
            if (reply.isEmpty()) continue;  // given up after 3 turns: the engine retries
            QCOMPARE(reply, QByteArray(":GNR") + QByteArray::number(device).rightJustified(2, '0'));
            ++answered;
        }
        qInfo() << answered << "of 200 answered at once;"
                << bus.line->medium().counters().damagedBlocks << "blocks damaged,"
                << bus.line->medium().counters().lostAcks << "acks lost";
        QVERIFY(bus.line->medium().counters().damagedBlocks > 0);
        QVERIFY(bus.line->medium().counters().lostAcks > 0);
        QVERIFY(answered >= 190);
        // A lost acknowledgement makes the sender repeat: never executed twice.
        QVERIFY(bus.line->device(7)->executions() <= 100);
    }
};

QTEST_GUILESS_MAIN(TestCamBusBus)
#include "tst_cambus_bus.moc"
