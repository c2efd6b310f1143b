// Issue 14: the MC-1 project file (the watch list with its names and last
// values) - round trip, and foreign or broken content refused by path.
#include "model/mc1/mc1_project_file.h"

#include <QTest>

using namespace cambench;

class TestMc1ProjectFile : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void roundTrip() {
        Mc1Project project;
        project.variant = QStringLiteral("mc100v2");
        project.variables = {{QStringLiteral("V12"), QStringLiteral("Feed length"), -5},
                             {QStringLiteral("V13"), QString(), std::nullopt}};
        project.flags = {{QStringLiteral("M2327"), QStringLiteral("Knife on"), 1}};
        const QByteArray json = mc1ProjectToJson(project);
        const Result<Mc1Project> read = mc1ProjectFromJson(json);
        QVERIFY2(read.ok(), qPrintable(read.error().message));
        QCOMPARE(read->variant, project.variant);
        QCOMPARE(read->variables.size(), 2);
        QCOMPARE(read->variables.at(0).name, QStringLiteral("Feed length"));
        QCOMPARE(*read->variables.at(0).value, qint64(-5));
        QVERIFY(!read->variables.at(1).value);
        QCOMPARE(read->flags.at(0).point, QStringLiteral("M2327"));
        QCOMPARE(mc1ProjectToJson(*read), json);
    }

    void brokenContentIsRefusedWhereItIs() {
        const struct {
            const char* json;
            const char* says;
        } cases[] = {
            {R"({"format":"cambench-mc1-project","version":1,"family":"mc1","variant":"mc300",
                "variables":[],"flags":[]})",
             "variant"},
            {R"({"format":"cambench-mc1-project","version":1,"family":"mc1","variant":"auto",
                "variables":[{"point":"M5","name":""}],"flags":[]})",
             "variables[0].point"},
            {R"({"format":"cambench-mc1-project","version":1,"family":"mc1","variant":"auto",
                "variables":[],"flags":[{"point":"A3","name":""},{"point":"a3","name":"x"}]})",
             "A3 a second time"},
            {R"({"format":"cambench-mc1-project","version":1,"family":"camcon","variant":"auto",
                "variables":[],"flags":[]})",
             "camcon"},
            {R"({"format":"cambench-mc1-project","version":9,"family":"mc1"})", "newer"},
        };
        for (const auto& c : cases) {
            const Result<Mc1Project> read = mc1ProjectFromJson(QByteArray(c.json));
            QVERIFY2(!read.ok(), c.json);
            QVERIFY2(read.error().message.contains(QLatin1String(c.says)),
                     qPrintable(read.error().message));
        }
    }
};

QTEST_GUILESS_MAIN(TestMc1ProjectFile)
#include "tst_mc1_project_file.moc"
