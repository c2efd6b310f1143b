#include "model/camcon/project_file.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

using namespace cambench;

namespace {

Project sampleProject() {
    Project project;
    project.device.epromDate = QStringLiteral("11.10.1994");
    project.device.outputs = 32;
    project.device.programs = 16;
    project.device.minPosition = 0;
    project.device.maxPosition = 359;

    CamProgram program;
    program.number = 3;
    program.name = QStringLiteral("Bottles 0,5 l");
    Track track;
    track.output = 5;
    track.cams = {{10, 50}, {100, 200}, {300, 5}};
    program.tracks.insert(5, track);
    track.output = 1;
    track.cams = {{0, 1}};
    program.tracks.insert(1, track);
    project.programs << program;
    CamProgram empty;
    empty.number = 0;
    empty.name = QStringLiteral("Leer");
    project.programs << empty;

    project.deadTimes = {{1, 12}, {2, 9999}};
    project.names.outputs = {{1, QStringLiteral("Glue \"hot\"")}, {5, QStringLiteral("Knife")}};
    project.names.programs = {{3, QStringLiteral("Bottles 0,5 l")}, {7, QStringLiteral("Spare")}};
    project.settings = {{QStringLiteral("gearMultiplier"), qint64(-5)},
                        {QStringLiteral("actualValueFormat"), QStringLiteral("###.#")},
                        {QStringLiteral("axisType"), qint64(0)}};

    User user;
    user.name = QStringLiteral("Anna");
    user.number = QStringLiteral("4711");
    user.outputAccess = QList<bool>(256, false);
    user.outputAccess[0] = true;
    user.outputAccess[255] = true;
    user.rights = User::Programming | User::UserMenu;
    project.users << user;

    PlcNetwork network;
    network.area = PlcNetwork::M;
    network.number = 10;
    network.value = -3;
    network.reset = 0x1234;
    network.symbols[0] = 0x0801;
    network.symbols[29] = 0xFFFF;
    project.plcNetworks << network;
    project.readAt.parts.insert(ProjectPart::Device,
                                QDateTime(QDate(2026, 3, 1), QTime(8, 30, 0, 125), Qt::UTC));
    project.readAt.parts.insert(ProjectPart::Users,
                                QDateTime(QDate(2026, 3, 1), QTime(8, 31, 5), Qt::UTC));
    project.readAt.programs.insert(3, QDateTime(QDate(2026, 3, 1), QTime(8, 30, 40), Qt::UTC));
    return project;
}

const ProjectSaveOptions kWithNumbers{true};

// The sample file with one value replaced (path of object keys and indexes).
QByteArray withValue(const QStringList& path, const QJsonValue& value) {
    std::function<QJsonValue(const QJsonValue&, int)> set = [&](const QJsonValue& node,
                                                                int depth) -> QJsonValue {
        if (depth == path.size()) return value;
        bool isIndex = false;
        const int index = path.at(depth).toInt(&isIndex);
        if (isIndex) {
            QJsonArray array = node.toArray();
            array[index] = set(array.at(index), depth + 1);
            return array;
        }
        QJsonObject object = node.toObject();
        object[path.at(depth)] = set(object.value(path.at(depth)), depth + 1);
        return object;
    };
    const QJsonObject root =
        QJsonDocument::fromJson(projectToJson(sampleProject(), kWithNumbers)).object();
    return QJsonDocument(set(root, 0).toObject()).toJson();
}

QString loadError(const QByteArray& bytes) {
    const Result<Project> result = projectFromJson(bytes);
    return result.ok() ? QString() : result.error().message;
}

}  // namespace

class TestProjectFile : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void sampleIsValid() { QCOMPARE(validateProject(sampleProject()), QStringList()); }

    void saveAndLoadRoundTrip() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("line1.cambench"));
        const Project project = sampleProject();
        const Status saved = saveProject(path, project, kWithNumbers);
        QVERIFY2(saved.ok(), qPrintable(saved.error().message));
        const Result<Project> loaded = loadProject(path);
        QVERIFY2(loaded.ok(), qPrintable(loaded.error().message));
        QCOMPARE(loaded->device, project.device);
        QCOMPARE(loaded->programs, project.programs);
        QCOMPARE(loaded->settings, project.settings);
        QCOMPARE(loaded->users, project.users);
        QCOMPARE(loaded->readAt, project.readAt);
        QVERIFY(*loaded == project);
    }

    // Issue 12, point 2: dead-time modes ride in the project; files from
    // before them load without; one device word cannot hold two values.
    void deadTimeModesRoundTrip() {
        Project project = sampleProject();
        project.device.deadTimeOutputs = 32;
        project.device.maxDeadTime = 9999;
        project.deadTimeModes = {{1, {DeadTimeMode::Normal, 12, 0, 0}},
                                 {2, {DeadTimeMode::SeparateOnOff, 9999, 80, 150}},
                                 {3, {DeadTimeMode::PathTime, 0, 20, 300}}};
        project.readAt.parts.insert(ProjectPart::DeadTimeModes,
                                    QDateTime(QDate(2026, 3, 1), QTime(8, 31, 9), Qt::UTC));
        QCOMPARE(validateProject(project), QStringList());
        const QByteArray json = projectToJson(project, kWithNumbers);
        const Result<Project> loaded = projectFromJson(json);
        QVERIFY2(loaded.ok(), qPrintable(loaded.error().message));
        QCOMPARE(loaded->deadTimeModes, project.deadTimeModes);
        QVERIFY(*loaded == project);

        // Without modes, the file has no such key and loads with none.
        QVERIFY(!projectToJson(sampleProject()).contains("deadTimeModes"));
        QVERIFY(projectFromJson(projectToJson(sampleProject()))->deadTimeModes.isEmpty());

        project.deadTimeModes[1].normal = 13;  // deadTimes says 12
        const QStringList problems = validateProject(project);
        QCOMPARE(problems.size(), 1);
        QVERIFY2(problems.first().contains(QLatin1String("Output 1")),
                 qPrintable(problems.first()));

        QByteArray bad = json;
        bad.replace("\"on/off\"", "\"sideways\"");
        const Result<Project> refused = projectFromJson(bad);
        QVERIFY(!refused.ok());
        QVERIFY2(refused.error().message.contains(QLatin1String("deadTimeModes[1].mode")),
                 qPrintable(refused.error().message));
    }

    // Issue 17: the user's minimum pulses (PC only) ride in the project;
    // a negative one or an output the device lacks is refused by path.
    void minimumPulsesRoundTrip() {
        Project project = sampleProject();
        project.minimumPulses = {{1, 125}, {project.device.outputs, 5}};
        const QByteArray json = projectToJson(project);
        QVERIFY(json.contains("minimumPulses"));
        const Result<Project> loaded = projectFromJson(json);
        QVERIFY2(loaded.ok(), qPrintable(loaded.error().message));
        QCOMPARE(loaded->minimumPulses, project.minimumPulses);
        QVERIFY(!projectToJson(sampleProject()).contains("minimumPulses"));

        QByteArray negative = json;
        negative.replace("\"minimumPulse\": 125", "\"minimumPulse\": -3");
        const Result<Project> refused = projectFromJson(negative);
        QVERIFY(!refused.ok());
        QVERIFY2(refused.error().message.contains(QLatin1String("minimumPulses[0]")),
                 qPrintable(refused.error().message));
    }

    void otherTableSectionsRoundTrip() {
        Project project = sampleProject();
        project.analogueCams = {AnalogueCamTrack{2, {{0, 100}, {90, -2000}}},
                                AnalogueCamTrack{3, {}}};
        project.programmingProgram = ProgrammingProgram{1, 2, 45};
        project.eepromLock = true;
        for (ProjectPart part :
             {ProjectPart::AnalogueCams, ProjectPart::ProgrammingProgram, ProjectPart::EepromLock})
            project.readAt.parts.insert(part, QDateTime(QDate(2026, 3, 1), QTime(8, 0), Qt::UTC));
        QCOMPARE(validateProject(project), QStringList());
        const QByteArray json = projectToJson(project, kWithNumbers);
        QVERIFY2(json.contains("\"selectMode\": \"at-value\""), json.constData());
        const Result<Project> loaded = projectFromJson(json);
        QVERIFY2(loaded.ok(), qPrintable(loaded.error().message));
        QVERIFY(*loaded == project);

        // Files without them say nothing about them.
        const Result<Project> plain = projectFromJson(projectToJson(sampleProject()));
        QVERIFY(plain->analogueCams.isEmpty());
        QVERIFY(!plain->programmingProgram.has_value());
        QVERIFY(!plain->eepromLock.has_value());

        // Values the device would refuse are warned about, naming the place.
        project.analogueCams[0].points = {{90, 1}, {10, 2}};
        project.programmingProgram->program = 99;
        const QString problems = validateProject(project).join(QLatin1Char('\n'));
        QVERIFY2(problems.contains(QLatin1String("Analogue output 2, base point 2")),
                 qPrintable(problems));
        QVERIFY2(problems.contains(QLatin1String("Programming program 99")), qPrintable(problems));

        QByteArray bad = json;
        bad.replace("\"at-value\"", "\"sometimes\"");
        Result<Project> refused = projectFromJson(bad);
        QVERIFY(!refused.ok());
        QVERIFY2(refused.error().message.contains(QLatin1String("programmingProgram.selectMode")),
                 qPrintable(refused.error().message));
        Project twice = sampleProject();
        twice.analogueCams = {AnalogueCamTrack{2, {}}, AnalogueCamTrack{2, {{0, 1}}}};
        refused = projectFromJson(projectToJson(twice));
        QVERIFY(!refused.ok());
        QVERIFY2(refused.error().message.contains(QLatin1String("analogue output 2 appears twice")),
                 qPrintable(refused.error().message));
    }

    void fileRecordsItsFamilyAndRefusesAnother() {
        const QByteArray json = projectToJson(sampleProject());
        QVERIFY2(json.contains("\"family\": \"camcon\""), json.constData());
        QByteArray other = json;
        other.replace("\"family\": \"camcon\"", "\"family\": \"mc1\"");
        const Result<Project> refused = projectFromJson(other);
        QVERIFY(!refused.ok());
        QVERIFY2(refused.error().message.contains(QLatin1String("family \"mc1\", not \"camcon\"")),
                 qPrintable(refused.error().message));
        // Files from before families were recorded are the CamCon's.
        QByteArray old = json;
        old.replace("\"family\": \"camcon\",", "");
        QVERIFY(!old.contains("family"));
        QVERIFY2(projectFromJson(old).ok(), old.constData());
    }

    void userNumbersAreSavedOnlyWhenAskedFor() {
        const QByteArray without = projectToJson(sampleProject());
        QVERIFY(!without.contains("4711"));
        const Result<Project> loaded = projectFromJson(without);
        QVERIFY2(loaded.ok(), qPrintable(loaded.error().message));
        QCOMPARE(loaded->users.size(), 1);
        QCOMPARE(loaded->users.first().number, QString());
        QCOMPARE(loaded->users.first().name, QStringLiteral("Anna"));
        // A user without a number is no problem of the project: it keeps
        // the device's number when written.
        QCOMPARE(validateProject(*loaded), QStringList());
        QVERIFY(projectToJson(sampleProject(), kWithNumbers).contains("\"4711\""));
    }

    void readTimesSayWhichPartsCameFromTheDevice() {
        const QJsonObject root = QJsonDocument::fromJson(projectToJson(sampleProject())).object();
        const QJsonObject readAt = root.value(QStringLiteral("readAt")).toObject();
        QCOMPARE(readAt.value(QStringLiteral("device")).toString(),
                 QStringLiteral("2026-03-01T08:30:00.125Z"));
        QVERIFY(!readAt.contains(QStringLiteral("settings")));
        QCOMPARE(readAt.value(QStringLiteral("programs")).toArray().size(), 1);
        // Program 0 is in the project but was not read; program 5 is not in
        // it at all ("not read"), which is not the same as empty.
        const Result<Project> loaded = projectFromJson(projectToJson(sampleProject()));
        QVERIFY(loaded.ok());
        QVERIFY(!loaded->readAt.programs.contains(0));
        QCOMPARE(loaded->programs.size(), 2);
        QVERIFY(loaded->programs.at(1).tracks.isEmpty());
    }

    void plcAreaNumbersOfOlderFilesStillLoad() {
        const QByteArray bytes = withValue(
            QStringLiteral("plcNetworks/0/area").split(QLatin1Char('/')), QJsonValue(0x0A));
        const Result<Project> loaded = projectFromJson(bytes);
        QVERIFY2(loaded.ok(), qPrintable(loaded.error().message));
        QCOMPARE(loaded->plcNetworks.first().area, int(PlcNetwork::M));
        QVERIFY(projectToJson(*loaded).contains("\"area\": \"M\""));
    }

    void savingTwiceGivesIdenticalBytes() {
        QTemporaryDir dir;
        const QString first = dir.filePath(QStringLiteral("a.cambench"));
        const QString second = dir.filePath(QStringLiteral("b.cambench"));
        QVERIFY(saveProject(first, sampleProject()).ok());
        const Result<Project> loaded = loadProject(first);
        QVERIFY(loaded.ok());
        QVERIFY(saveProject(second, *loaded).ok());
        QFile a(first), b(second);
        QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
        const QByteArray bytes = a.readAll();
        QCOMPARE(bytes, b.readAll());
        QVERIFY(bytes.contains("\"format\": \"cambench-project\""));
    }

    void camsAreWrittenAsPairs() {
        const QJsonObject root =
            QJsonDocument::fromJson(projectToJson(sampleProject(), kWithNumbers)).object();
        const QJsonArray cams =
            root[QStringLiteral("programs")][0][QStringLiteral("tracks")][1][QStringLiteral("cams")]
                .toArray();
        QCOMPARE(cams.size(), 3);
        QCOMPARE(cams.at(2).toArray(), (QJsonArray{300, 5}));
    }

    void notJsonIsRejected() {
        const QString error = loadError("this is no json {");
        QVERIFY2(error.contains(QStringLiteral("not valid JSON")), qPrintable(error));
    }

    void truncatedFileIsRejected() {
        const QByteArray bytes = projectToJson(sampleProject());
        QVERIFY(loadError(bytes.left(bytes.size() / 2)).contains(QStringLiteral("not valid JSON")));
    }

    void wrongFormatIsRejected() {
        const QString error = loadError(R"({"format":"cambench-eeprom-image","version":1})");
        QVERIFY2(error.contains(QStringLiteral("not a CamBench project")), qPrintable(error));
        QVERIFY(loadError(R"({"name":"package.json"})")
                    .contains(QStringLiteral("not a CamBench project")));
        QVERIFY(loadError("[1,2,3]").contains(QStringLiteral("not a CamBench project")));
    }

    void newerVersionAsksForNewerCamBench() {
        const QString error = loadError(withValue({QStringLiteral("version")}, 2));
        QVERIFY2(error.contains(QStringLiteral("newer CamBench")), qPrintable(error));
        QVERIFY(error.contains(QStringLiteral("version 2")));
    }

    void badValueIsReportedWithItsPath_data() {
        QTest::addColumn<QStringList>("path");
        QTest::addColumn<QJsonValue>("value");
        QTest::addColumn<QString>("expected");
        const auto p = [](const char* text) {
            return QString::fromLatin1(text).split(QLatin1Char('/'));
        };
        QTest::newRow("cam point not integer")
            << p("programs/0/tracks/1/cams/2/1") << QJsonValue(2.5)
            << QStringLiteral("programs[0].tracks[1].cams[2]: switch-off point is not an integer.");
        QTest::newRow("cam point a string")
            << p("programs/0/tracks/1/cams/0/0") << QJsonValue(QStringLiteral("10"))
            << QStringLiteral("programs[0].tracks[1].cams[0]: switch-on point is not an integer.");
        QTest::newRow("output beyond device")
            << p("programs/0/tracks/1/output") << QJsonValue(33)
            << QStringLiteral("programs[0].tracks[1].output: output 33 is outside 1..32.");
        QTest::newRow("program beyond device")
            << p("programs/0/number") << QJsonValue(16)
            << QStringLiteral("programs[0].number: program number 16 is outside 0..15.");
        QTest::newRow("missing key") << p("device/outputs") << QJsonValue(QJsonValue::Undefined)
                                     << QStringLiteral("device: \"outputs\" is missing.");
        QTest::newRow("outputs not multiple of 8")
            << p("device/outputs") << QJsonValue(12)
            << QStringLiteral("device.outputs: number of outputs 12 is not a multiple of 8.");
        QTest::newRow("unknown setting")
            << p("settings/warpDrive") << QJsonValue(1)
            << QStringLiteral("settings.warpDrive: there is no such setting.");
        QTest::newRow("plc symbol too large")
            << p("plcNetworks/0/symbols/3") << QJsonValue(65536)
            << QStringLiteral("plcNetworks[0].symbols[3]: symbol 65536 is outside 0..65535.");
        QTest::newRow("programs not an array")
            << p("programs") << QJsonValue(5)
            << QStringLiteral("programs: a JSON array is expected.");
    }

    void badValueIsReportedWithItsPath() {
        QFETCH(QStringList, path);
        QFETCH(QJsonValue, value);
        QFETCH(QString, expected);
        QCOMPARE(loadError(withValue(path, value)), expected);
    }

    // Values a device could hold load and save as they are; validation
    // warns about them (issue 6: the device's own values must never stop a
    // project from being saved).
    void devicesValuesLoadWithAWarning_data() {
        QTest::addColumn<QStringList>("path");
        QTest::addColumn<QJsonValue>("value");
        QTest::addColumn<QString>("warning");
        const auto p = [](const char* text) {
            return QString::fromLatin1(text).split(QLatin1Char('/'));
        };
        QTest::newRow("cam above maximum")
            << p("programs/0/tracks/1/cams/1/1") << QJsonValue(400)
            << QStringLiteral(
                   "program 3, output 5, cam 2: switch-off point 400 is above the "
                   "maximum 359.");
        QTest::newRow("overlap") << p("programs/0/tracks/1/cams/1/0") << QJsonValue(40)
                                 << QStringLiteral(
                                        "program 3, output 5, cam 2: 40..200 overlaps cam 1 "
                                        "(10..50).");
        QTest::newRow("wrapping cam on a linear axis")
            << p("settings/axisType") << QJsonValue(1)
            << QStringLiteral(
                   "program 3, output 5, cam 3: switch-off point 5 is below the "
                   "switch-on point 300; only on a rotary axis may a cam wrap through "
                   "zero.");
        QTest::newRow("dead time too large")
            << p("deadTimes/1/deadTime") << QJsonValue(10000)
            << QStringLiteral("Dead time of output 2: 10000 is outside 0..9999 (0.1 ms steps).");
        QTest::newRow("setting out of range")
            << p("settings/gearMultiplier") << QJsonValue(0)
            << QStringLiteral(
                   "gearMultiplier: 0 is not allowed; allowed are -99999..-1 and 1..99999.");
        QTest::newRow("name too long")
            << p("outputNames/0/name") << QJsonValue(QString(22, QLatin1Char('x')))
            << QStringLiteral(
                   "Name of output 1: \"xxxxxxxxxxxxxxxxxxxxxx\" has 22 characters; "
                   "the device stores at most 21.");
        QTest::newRow("user number DEL")
            << p("users/0/number") << QJsonValue(QStringLiteral("DEL"))
            << QStringLiteral(
                   "User 1 (\"Anna\"): the user number \"DEL\" is reserved: it "
                   "deletes a user.");
    }

    void devicesValuesLoadWithAWarning() {
        QFETCH(QStringList, path);
        QFETCH(QJsonValue, value);
        QFETCH(QString, warning);
        const Result<Project> loaded = projectFromJson(withValue(path, value));
        QVERIFY2(loaded.ok(), qPrintable(loaded.error().message));
        const QStringList warnings = validateProject(*loaded);
        QVERIFY2(warnings.contains(warning), qPrintable(warnings.join(u'\n')));
        // ... and the value survives a save.
        const Result<Project> again = projectFromJson(projectToJson(*loaded, kWithNumbers));
        QVERIFY(again.ok());
        QVERIFY(*again == *loaded);
    }

    void loadErrorNamesTheFile() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("broken.cambench"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("{");
        file.close();
        const Result<Project> result = loadProject(path);
        QVERIFY(!result.ok());
        QCOMPARE(result.error().kind, ErrorKind::InvalidData);
        QVERIFY(result.error().message.startsWith(path + QStringLiteral(": ")));
        QVERIFY(!loadProject(dir.filePath(QStringLiteral("missing.cambench"))).ok());
    }

    void projectWithWarningsIsSaved() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("bad.cambench"));
        Project project = sampleProject();
        project.programs[0].tracks[5].cams << Cam{40, 60};
        QVERIFY(validateProject(project).join(u' ').contains(QStringLiteral("overlaps")));
        const Status saved = saveProject(path, project, kWithNumbers);
        QVERIFY2(saved.ok(), qPrintable(saved.error().message));
        const Result<Project> loaded = loadProject(path);
        QVERIFY(loaded.ok());
        QVERIFY(*loaded == project);
    }

    void programNameMustAgreeWithNameList() {
        Project project = sampleProject();
        project.names.programs[3] = QStringLiteral("Cans");
        const QStringList problems = validateProject(project);
        QCOMPARE(problems.size(), 1);
        QVERIFY(problems.first().contains(QStringLiteral("Cans")));
    }
};

QTEST_GUILESS_MAIN(TestProjectFile)
#include "tst_project_file.moc"
