#include "model/camcon/data_validation.h"

#include <QtTest>

using namespace cambench;

namespace {

User user(const QString& name, const QString& number) {
    User u;
    u.name = name;
    u.number = number;
    u.outputAccess = QList<bool>(256, false);
    return u;
}

}  // namespace

class TestDataValidation : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void deadTimesWithinDeviceLimitsAreValid() {
        DeviceInfo device;
        device.deadTimeOutputs = 16;
        device.maxDeadTime = 500;
        QVERIFY(validateDeadTimes({{1, 0}, {16, 500}}, device).isEmpty());
    }

    void deadTimeOutsideLimitsNamesOutputAndRange() {
        DeviceInfo device;
        device.deadTimeOutputs = 16;
        device.maxDeadTime = 500;
        const QStringList tooLarge = validateDeadTimes({{3, 501}}, device);
        QCOMPARE(tooLarge.size(), 1);
        QVERIFY(tooLarge.first().contains(QStringLiteral("output 3")));
        QVERIFY(tooLarge.first().contains(QStringLiteral("0..500")));
        QCOMPARE(validateDeadTimes({{3, -1}}, device).size(), 1);
        QCOMPARE(validateDeadTimes({{17, 1}}, device).size(), 1);
        QCOMPARE(validateDeadTimes({{0, 1}}, device).size(), 1);
    }

    void nameRules() {
        QVERIFY(nameProblem(QString()).isEmpty());
        QVERIFY(nameProblem(QString(21, QLatin1Char('x'))).isEmpty());
        QVERIFY(nameProblem(QStringLiteral("Förderband Ä")).isEmpty());
        QVERIFY(
            nameProblem(QString(22, QLatin1Char('x'))).contains(QStringLiteral("22 characters")));
        QVERIFY(nameProblem(QStringLiteral("Euro €")).contains(QStringLiteral("Latin-1")));
        QVERIFY(!nameProblem(QStringLiteral("tab\there")).isEmpty());
    }

    void namesOutsideDeviceRange() {
        DeviceInfo device;
        device.outputs = 16;
        device.programs = 4;
        Names names;
        names.outputs = {{1, QStringLiteral("Glue")}, {17, QStringLiteral("x")}};
        names.programs = {{3, QStringLiteral("ok")}, {4, QStringLiteral("y")}};
        const QStringList problems = validateNames(names, device);
        QCOMPARE(problems.size(), 2);
        QVERIFY(problems.at(0).contains(QStringLiteral("output 17")));
        QVERIFY(problems.at(1).contains(QStringLiteral("program 4")));
    }

    void userNumberRules() {
        QVERIFY(userProblem(user(QStringLiteral("Anna"), QStringLiteral("12345"))).isEmpty());
        QVERIFY(userProblem(user(QStringLiteral("Anna"), QStringLiteral("a1"))).isEmpty());
        QVERIFY(!userProblem(user(QStringLiteral("Anna"), QString())).isEmpty());
        QVERIFY(!userProblem(user(QStringLiteral("Anna"), QStringLiteral("123456"))).isEmpty());
        QVERIFY(!userProblem(user(QStringLiteral("Anna"), QStringLiteral("DEL"))).isEmpty());
        QVERIFY(!userProblem(user(QStringLiteral("Anna"), QStringLiteral("1\x01"))).isEmpty());
        QVERIFY(!userProblem(user(QString(22, QLatin1Char('n')), QStringLiteral("1"))).isEmpty());
    }

    void userProblemsNeverShowTheNumber() {
        const QStringList problems =
            validateUsers({user(QStringLiteral("Anna"), QStringLiteral("4711")),
                           user(QStringLiteral("Bert"), QStringLiteral("4711")),
                           user(QStringLiteral("Carl"), QStringLiteral("DEL"))});
        QCOMPARE(problems.size(), 2);
        QVERIFY(problems.at(0).contains(QStringLiteral("user 1")));
        for (const QString& p : problems)
            QVERIFY2(!p.contains(QStringLiteral("4711")), qPrintable(p));
    }

    void plcNetworkAreaAndNumber() {
        PlcNetwork network;
        network.area = PlcNetwork::X;
        network.number = kMaxPlcNumber;
        QVERIFY(validatePlcNetwork(network).isEmpty());
        network.area = 0x0C;
        QCOMPARE(validatePlcNetwork(network).size(), 1);
        network.area = PlcNetwork::O;
        network.number = kMaxPlcNumber + 1;
        QCOMPARE(validatePlcNetwork(network).size(), 1);
        network.number = -1;
        QCOMPARE(validatePlcNetwork(network).size(), 1);
    }

    void plcNetworkIsEmptyOnlyWithoutContent() {
        PlcNetwork network;
        network.number = 7;
        QVERIFY(network.isEmpty());
        network.symbols[29] = 0x0101;
        QVERIFY(!network.isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestDataValidation)
#include "tst_data_validation.moc"
