#include "comm/camcon/table/cam_track_words.h"
#include "comm/camcon/table/rk512_planner.h"
#include "comm/camcon/table/table_map.h"

#include <QSet>
#include <QtTest>

#include <cstring>

using namespace cambench;
using namespace cambench::comm::table;

class TestTableMap : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void keysAreUniqueAndWellFormed();
    void entriesStayInsideTheirAreasAndNeverOverlap();
    void onlyPlcValueAreasListWordsBeyond255();
    void provisionalEntriesGiveAReason();
    void findsEntriesByKey();
    void locatesWordsByAreaAndWord_data();
    void locatesWordsByAreaAndWord();
    void listsEntriesOfAnArea();
    void describesSpecialEncoders();

    void wholeTrackWriteStartsAtCamOne();
    void wholeTrackWritePadsToTwoCams();
    void wholeTrackWriteRefusesWhatTheDeviceWouldMisread();
    void singleCamWriteTouchesOnlyThatCam();
    void deleteWritesEqualPoints();
    void trackWordsConvertBackToCams();
    void trackWordsRejectHalfEmptyPairs();
    void fullTrackPlansIntoWholeCamTelegrams();
};

void TestTableMap::keysAreUniqueAndWellFormed() {
    QSet<QString> keys;
    for (const TableEntry& entry : tableEntries()) {
        const QString key = QLatin1String(entry.key);
        QVERIFY2(!keys.contains(key), qPrintable(key));
        keys.insert(key);
        QVERIFY2(key.contains('.'), qPrintable(key));
        QVERIFY2(key == key.toLower() && !key.contains(' '), qPrintable(key));
        QVERIFY2(std::strlen(entry.meaning) > 0, qPrintable(key));
        QVERIFY(entry.unit != nullptr);
    }
    QVERIFY(keys.size() > 150);
}

void TestTableMap::entriesStayInsideTheirAreasAndNeverOverlap() {
    for (const TableEntry& entry : tableEntries()) {
        QVERIFY2(entry.firstArea >= 1 && entry.firstArea <= entry.lastArea && entry.lastArea <= 255,
                 entry.key);
        QVERIFY2(entry.count >= 1 && entry.stride >= 1 && entry.firstWord >= 0, entry.key);
    }
    for (int area = 1; area <= 255; ++area) {
        QHash<int, const char*> owner;
        for (const TableEntry* entry : tableEntriesOfArea(area)) {
            for (int i = 0; i < entry->count; ++i) {
                const int word = entry->wordOf(i);
                QVERIFY2(!owner.contains(word),
                         qPrintable(QStringLiteral("area %1 word %2: %3 and %4")
                                        .arg(area)
                                        .arg(word)
                                        .arg(owner.value(word), entry->key)));
                owner.insert(word, entry->key);
                QCOMPARE(entry->indexOf(word), i);
            }
        }
    }
}

void TestTableMap::onlyPlcValueAreasListWordsBeyond255() {
    QStringList beyond;
    for (const TableEntry& entry : tableEntries()) {
        if (entry.lastWord() >= kWordsPerArea) beyond.append(QLatin1String(entry.key));
    }
    QCOMPARE(beyond, (QStringList{"plc.set_p", "plc.set_m", "plc.set_x", "plc.actual_p",
                                  "plc.actual_m", "plc.actual_x"}));
}

void TestTableMap::provisionalEntriesGiveAReason() {
    QStringList provisional;
    for (const TableEntry& entry : tableEntries()) {
        if (!entry.provisional) continue;
        QVERIFY2(std::strlen(entry.provisional) > 10, entry.key);
        provisional.append(QLatin1String(entry.key));
    }
    QVERIFY(provisional.contains("plc_link.symbol"));
    QVERIFY(provisional.contains("track.dead_time_off"));
    QVERIFY(provisional.contains("status.eprom_date"));
    QVERIFY(!provisional.contains("config.eeprom_lock"));
}

void TestTableMap::findsEntriesByKey() {
    const TableEntry* lock = findTableEntry(u"config.eeprom_lock");
    QVERIFY(lock);
    QCOMPARE(lock->firstArea, kConfigArea);
    QCOMPARE(lock->firstWord, 4);
    QCOMPARE(lock->access, TableAccess::ReadWrite);

    const TableEntry* clearAll = findTableEntry(u"config.clear_all");
    QVERIFY(clearAll && !canRead(clearAll->access) && canWrite(clearAll->access));

    const TableEntry* actual = findTableEntry(u"status.actual_value");
    QVERIFY(actual && actual->firstArea == kStatusArea && actual->firstWord == 0);

    const TableEntry* speed = findTableEntry(u"status.speed");
    QVERIFY(speed && canRead(speed->access) && !canWrite(speed->access));

    const TableEntry* deadTime = findTableEntry(u"track.dead_time");
    QVERIFY(deadTime);
    QCOMPARE(deadTime->firstArea, kFirstTrackArea);
    QCOMPARE(deadTime->lastArea, kLastTrackArea);
    QCOMPARE(QByteArray(deadTime->unit), QByteArray("0.1 ms"));

    const TableEntry* mode = findTableEntry(u"track.dead_time_mode");
    QVERIFY(mode && mode->firstWord == 251);

    const TableEntry* encoder = findTableEntry(u"system.special_encoder_parameter");
    QVERIFY(encoder && encoder->firstWord == 2 && encoder->count == 6);

    QVERIFY(!findTableEntry(u"status.nothing"));
    QVERIFY(!findTableEntry(u""));
}

void TestTableMap::locatesWordsByAreaAndWord_data() {
    QTest::addColumn<int>("area");
    QTest::addColumn<int>("word");
    QTest::addColumn<QString>("key");  // empty = free word
    QTest::addColumn<int>("index");
    QTest::newRow("dead time of output 17") << 17 << 0 << "track.dead_time" << 0;
    QTest::newRow("cam 1 on") << 1 << 1 << "track.cam_on" << 0;
    QTest::newRow("cam 3 on") << 17 << 5 << "track.cam_on" << 2;
    QTest::newRow("cam 3 off") << 17 << 6 << "track.cam_off" << 2;
    QTest::newRow("cam 125 off") << 200 << 250 << "track.cam_off" << 124;
    QTest::newRow("dead-time mode") << 3 << 251 << "track.dead_time_mode" << 0;
    QTest::newRow("dead time on") << 3 << 252 << "track.dead_time_on" << 0;
    QTest::newRow("dead time off") << 3 << 253 << "track.dead_time_off" << 0;
    QTest::newRow("cam count") << 3 << 254 << "track.cam_count" << 0;
    QTest::newRow("track word 255 free") << 3 << 255 << "" << 0;
    QTest::newRow("program") << 201 << 2 << "status.program" << 0;
    QTest::newRow("analogue output 1") << 201 << 3 << "status.analog_output" << 0;
    QTest::newRow("analogue output 14") << 201 << 16 << "status.analog_output" << 13;
    QTest::newRow("device status") << 201 << 34 << "status.device_status" << 0;
    QTest::newRow("201 word 54 free") << 201 << 54 << "" << 0;
    QTest::newRow("201 word 67 unlisted") << 201 << 67 << "" << 0;
    QTest::newRow("programming program") << 201 << 70 << "status.programming_program" << 0;
    QTest::newRow("outputs 33..64") << 202 << 1 << "io.outputs" << 1;
    QTest::newRow("202 reserve") << 202 << 7 << "" << 0;
    QTest::newRow("V1..V32") << 202 << 48 << "io.virtual_inputs" << 0;
    QTest::newRow("S961..S992") << 202 << 254 << "io.special_inputs_ext" << 22;
    QTest::newRow("gear divisor") << 203 << 11 << "system.gear_divisor" << 0;
    QTest::newRow("master outputs 225..256") << 203 << 62 << "system.master_program_outputs" << 7;
    QTest::newRow("analogue 2 min") << 204 << 7 << "analog_out.min" << 1;
    QTest::newRow("analogue 14 offset") << 204 << 97 << "analog_out.offset" << 13;
    QTest::newRow("204 word 98 free") << 204 << 98 << "" << 0;
    QTest::newRow("EEPROM lock") << 205 << 4 << "config.eeprom_lock" << 0;
    QTest::newRow("O5 set value") << 206 << 4 << "plc.set_o" << 4;
    QTest::newRow("M1 actual value") << 212 << 0 << "plc.actual_m" << 0;
    QTest::newRow("multi-cam percent count") << 214 << 11 << "multicam_percent.count" << 0;
    QTest::newRow("path 4 symbol 5") << 216 << 35 << "plc_link.symbol" << 29;
    QTest::newRow("analogue cam base 1") << 241 << 1 << "analog_cam.base" << 0;
    QTest::newRow("analogue cam value 125") << 254 << 250 << "analog_cam.value" << 124;
    QTest::newRow("analogue cam count") << 248 << 254 << "analog_cam.count" << 0;
    QTest::newRow("analogue cam word 0 free") << 241 << 0 << "" << 0;
    QTest::newRow("area 215 upon request") << 215 << 0 << "" << 0;
    QTest::newRow("area 255 undescribed") << 255 << 0 << "" << 0;
    QTest::newRow("negative word") << 5 << -1 << "" << 0;
}

void TestTableMap::locatesWordsByAreaAndWord() {
    QFETCH(int, area);
    QFETCH(int, word);
    QFETCH(QString, key);
    QFETCH(int, index);
    const std::optional<TableLocation> location = locateTableWord(area, word);
    if (key.isEmpty()) {
        QVERIFY2(!location, location ? location->entry->key : "");
        return;
    }
    QVERIFY(location.has_value());
    QCOMPARE(QString::fromLatin1(location->entry->key), key);
    QCOMPARE(location->index, index);
    QCOMPARE(location->entry->wordOf(location->index), word);
}

void TestTableMap::listsEntriesOfAnArea() {
    const QList<const TableEntry*> config = tableEntriesOfArea(kConfigArea);
    QCOMPARE(config.size(), 13);
    for (int i = 0; i < config.size(); ++i) QCOMPARE(config[i]->firstWord, i);
    const QList<const TableEntry*> track = tableEntriesOfArea(42);
    QStringList keys;
    for (const TableEntry* entry : track) keys.append(QLatin1String(entry->key));
    QCOMPARE(keys, (QStringList{"track.dead_time", "track.cam_on", "track.cam_off",
                                "track.dead_time_mode", "track.dead_time_on", "track.dead_time_off",
                                "track.cam_count"}));
    QVERIFY(tableEntriesOfArea(215).isEmpty());
    QVERIFY(tableEntriesOfArea(0).isEmpty());
}

void TestTableMap::describesSpecialEncoders() {
    QCOMPARE(specialEncoderLayouts().size(), 11);
    for (int type = 0; type <= 10; ++type) {
        const SpecialEncoderLayout* layout = findSpecialEncoderLayout(type);
        QVERIFY(layout);
        QCOMPARE(layout->type, type);
        QVERIFY(std::strlen(layout->parameters[0]) > 0);
    }
    QVERIFY(!findSpecialEncoderLayout(11));
    QVERIFY(!findSpecialEncoderLayout(-1));
    const SpecialEncoderLayout* pll = findSpecialEncoderLayout(4);
    QCOMPARE(QByteArray(pll->key), QByteArray("pll"));
    QCOMPARE(QByteArray(pll->parameters[5]), QByteArray("sync_output"));
    const SpecialEncoderLayout* ssi = findSpecialEncoderLayout(0);
    QCOMPARE(QByteArray(ssi->parameters[3]), QByteArray("error_bit"));
    QCOMPARE(QByteArray(ssi->parameters[4]), QByteArray(""));
    QVERIFY(findSpecialEncoderLayout(6)->provisional);
    QVERIFY(!findSpecialEncoderLayout(9)->provisional);
}

void TestTableMap::wholeTrackWriteStartsAtCamOne() {
    const Result<TrackWrite> write = wholeTrackWrite({{10, 20}, {30, 40}, {350, 5}});
    QVERIFY(write.ok());
    QCOMPARE(write->firstWord, 1);
    QCOMPARE(write->words, (QList<qint32>{10, 20, 30, 40, 350, 5}));
}

void TestTableMap::wholeTrackWritePadsToTwoCams() {
    // Fewer than 2 cams would change cam 1 only instead of replacing the track.
    const QList<qint32> empty{kEmptyCamWord, kEmptyCamWord};
    QCOMPARE(wholeTrackWrite({{10, 20}})->words, QList<qint32>({10, 20}) + empty);
    QCOMPARE(wholeTrackWrite({})->words, empty + empty);
    QCOMPARE(wholeTrackWrite({})->firstWord, 1);
    QCOMPARE(kRewritePaddingWord, qint32(0x80000000u));
}

void TestTableMap::wholeTrackWriteRefusesWhatTheDeviceWouldMisread() {
    QList<Cam> many;
    for (int i = 0; i < 126; ++i) many.append({i * 10, i * 10 + 5});
    const Result<TrackWrite> tooMany = wholeTrackWrite(many);
    QCOMPARE(tooMany.error().kind, ErrorKind::InvalidData);
    QVERIFY2(tooMany.error().message.contains("125"), qPrintable(tooMany.error().message));
    many.removeLast();
    QCOMPARE(wholeTrackWrite(many)->words.size(), 250);

    const Result<TrackWrite> equal = wholeTrackWrite({{10, 20}, {30, 30}});
    QCOMPARE(equal.error().kind, ErrorKind::InvalidData);
    QVERIFY2(equal.error().message.contains("Cam 2") && equal.error().message.contains("delete"),
             qPrintable(equal.error().message));
    QCOMPARE(wholeTrackWrite({{kEmptyCamWord, 20}}).error().kind, ErrorKind::InvalidData);
    QCOMPARE(wholeTrackWrite({{20, kEmptyCamWord}}).error().kind, ErrorKind::InvalidData);
}

void TestTableMap::singleCamWriteTouchesOnlyThatCam() {
    const Result<TrackWrite> first = singleCamWrite(1, {100, 200});
    QVERIFY(first.ok());
    QCOMPARE(*first, (TrackWrite{1, {100, 200}}));  // 8 bytes: no whole-track rewrite
    QCOMPARE(*singleCamWrite(3, {-50, 60}), (TrackWrite{5, {-50, 60}}));
    QCOMPARE(singleCamWrite(125, {1, 2})->firstWord, 249);
    QCOMPARE(singleCamWrite(0, {1, 2}).error().kind, ErrorKind::Usage);
    QCOMPARE(singleCamWrite(126, {1, 2}).error().kind, ErrorKind::Usage);
    QCOMPARE(singleCamWrite(2, {7, 7}).error().kind, ErrorKind::InvalidData);
    QCOMPARE(camOnWord(3), 5);
    QCOMPARE(camOffWord(3), 6);
    QCOMPARE(locateTableWord(9, camOnWord(125))->entry->key, findTableEntry(u"track.cam_on")->key);
}

void TestTableMap::deleteWritesEqualPoints() {
    const Result<TrackWrite> remove = camDeleteWrite(2);
    QVERIFY(remove.ok());
    QCOMPARE(remove->firstWord, 3);
    QCOMPARE(remove->words.size(), 2);
    QCOMPARE(remove->words[0], remove->words[1]);
    QCOMPARE(camDeleteWrite(126).error().kind, ErrorKind::Usage);
}

void TestTableMap::trackWordsConvertBackToCams() {
    const QList<Cam> cams{{-100, 20}, {30, 40}, {350, 5}};
    const Result<TrackWrite> write = wholeTrackWrite(cams);
    QCOMPARE(*camsFromTrackWords(write->words), cams);
    // A read of the whole track: the rest of the places are empty.
    QList<qint32> words = write->words;
    while (words.size() < 250) words.append(kEmptyCamWord);
    QCOMPARE(*camsFromTrackWords(words), cams);
    // Padding of a short rewrite reads back as no cam.
    QCOMPARE(*camsFromTrackWords(wholeTrackWrite({{1, 2}})->words), (QList<Cam>{{1, 2}}));
    QVERIFY(camsFromTrackWords(wholeTrackWrite({})->words)->isEmpty());
    // An empty place between cams is skipped.
    QCOMPARE(*camsFromTrackWords({1, 2, kEmptyCamWord, kEmptyCamWord, 5, 6}),
             (QList<Cam>{{1, 2}, {5, 6}}));
}

void TestTableMap::trackWordsRejectHalfEmptyPairs() {
    QCOMPARE(camsFromTrackWords({1, kEmptyCamWord}).error().kind, ErrorKind::InvalidData);
    QCOMPARE(camsFromTrackWords({kEmptyCamWord, 1}).error().kind, ErrorKind::InvalidData);
    QCOMPARE(camsFromTrackWords({4, 4}).error().kind, ErrorKind::InvalidData);
    QCOMPARE(camsFromTrackWords({1, 2, 3}).error().kind, ErrorKind::Usage);
    QCOMPARE(camsFromTrackWords(QList<qint32>(252, 1)).error().kind, ErrorKind::Usage);
}

void TestTableMap::fullTrackPlansIntoWholeCamTelegrams() {
    QList<Cam> cams;
    for (int i = 0; i < 125; ++i) cams.append({i * 100, i * 100 + 50});
    const Result<TrackWrite> write = wholeTrackWrite(cams);
    const Result<QList<Rk512Request>> requests =
        planTableWrite(Rk512Variant::N96, 12, write->firstWord, write->words);
    QVERIFY(requests.ok());
    QCOMPARE(requests->size(), 8);
    // The first telegram starts at cam 1 with 16 cams: it replaces the track.
    QCOMPARE(requests->first().offset, 1);
    QCOMPARE(requests->first().words16, 64);
    QList<Cam> sent;
    for (const Rk512Request& request : *requests) {
        QCOMPARE(request.offset % 2, 1);   // each begins at a switch-on point
        QCOMPARE(request.words16 % 4, 0);  // whole cams (2 table words = 4 16-bit words)
        sent += *camsFromTrackWords(*bytesToTableWords(request.data));
    }
    QCOMPARE(sent, cams);
}

QTEST_GUILESS_MAIN(TestTableMap)
#include "tst_table_map.moc"
