#include "model/camcon/system_settings.h"

#include <QSet>
#include <QtTest>

using namespace cambench;

class TestSystemSettings : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void everySpecIsComplete() {
        QSet<QString> keys;
        for (const SettingSpec& spec : settingSpecs()) {
            const QString key = QLatin1String(spec.key);
            QVERIFY2(!keys.contains(key), qPrintable(key));
            keys.insert(key);
            QVERIFY2(*spec.group && *spec.label && *spec.tooltip && *spec.section, qPrintable(key));
            if (spec.kind == SettingKind::Text)
                QVERIFY2(spec.maxLength > 0, qPrintable(key));
            else
                QVERIFY2(spec.min <= spec.max, qPrintable(key));
            if (spec.kind == SettingKind::Enum) QVERIFY2(!spec.choices.isEmpty(), qPrintable(key));
            QCOMPARE(findSetting(key), &spec);
        }
        QVERIFY(findSetting(QStringLiteral("noSuchSetting")) == nullptr);
    }

    void tableCoversTheManualsSingleValues() {
        for (const char* key :
             {"encoderType", "actualValueHysteresis", "gearMultiplier", "speedFactor",
              "speedAccuracy", "cableLength", "actualCycleTime", "outputCount", "protocol",
              "deviceNumber", "plcMode", "specialEncoder.type", "specialEncoder.ssi.resolutionBits",
              "specialEncoder.timer.clearInput", "programSelection.mode"})
            QVERIFY2(findSetting(QLatin1String(key)), key);
        QVERIFY(findSetting(QStringLiteral("actualCycleTime"))->readOnly);
        QVERIFY(findSetting(QStringLiteral("specialEncoder.type"))->readOnly);
        QVERIFY(!findSetting(QStringLiteral("offset"))->readOnly);
    }

    void encoderListHasReadableNames() {
        const SettingSpec* spec = findSetting(QStringLiteral("encoderType"));
        QCOMPARE(spec->kind, SettingKind::Enum);
        QCOMPARE(spec->choices.size(), 22);
        QCOMPARE(spec->choices.last().value, 0xFF);
        QVERIFY(QByteArray(spec->choices.last().label).contains("special encoder"));
    }

    void validSettingsPass() {
        const SystemSettings settings{
            {QStringLiteral("actualValueHysteresis"), 125},
            {QStringLiteral("gearMultiplier"), -99999},
            {QStringLiteral("speedFactor"), qint64(99999999)},
            {QStringLiteral("outputCount"), 200},
            {QStringLiteral("encoderType"), 0xFF},
            {QStringLiteral("actualValueFormat"), QStringLiteral("####.#")},
            {QStringLiteral("presetInput"), 0},
        };
        QCOMPARE(validateSettings(settings), QStringList());
    }

    void outOfRangeNamesKeyAndRange() {
        const QStringList problems =
            validateSettings({{QStringLiteral("actualValueHysteresis"), 126}});
        QCOMPARE(problems,
                 QStringList{QStringLiteral("actualValueHysteresis: 126 is outside the allowed "
                                            "range 0..125.")});
    }

    void gearMultiplierRejectsZero() {
        const QStringList problems = validateSettings({{QStringLiteral("gearMultiplier"), 0}});
        QCOMPARE(problems.size(), 1);
        QVERIFY(problems.first().contains(QStringLiteral("-99999..-1 and 1..99999")));
    }

    void fixedValuesShowTheirDecimals() {
        const QStringList problems = validateSettings({{QStringLiteral("speedFactor"), 0}});
        QCOMPARE(problems.size(), 1);
        QVERIFY2(problems.first().contains(QStringLiteral("0.00001..999.99999")),
                 qPrintable(problems.first()));
        const SettingSpec* accuracy = findSetting(QStringLiteral("speedAccuracy"));
        QCOMPARE(formatSettingValue(*accuracy, 5), QStringLiteral("0.05"));
        QCOMPARE(formatSettingValue(*accuracy, -105), QStringLiteral("-1.05"));
    }

    void countsMustBeMultiplesOfEight() {
        const QStringList problems = validateSettings({{QStringLiteral("outputCount"), 12}});
        QCOMPARE(problems.size(), 1);
        QVERIFY(problems.first().contains(QStringLiteral("multiple of 8")));
        QCOMPARE(validateSettings({{QStringLiteral("outputCount"), 0}}).size(), 1);
    }

    void enumRejectsUnlistedValue() {
        const QStringList problems = validateSettings({{QStringLiteral("encoderType"), 0x15}});
        QCOMPARE(problems.size(), 1);
        QVERIFY2(problems.first().contains(QStringLiteral("0..20, 255")),
                 qPrintable(problems.first()));
    }

    void textTooLongOrWrongType() {
        QCOMPARE(
            validateSettings({{QStringLiteral("actualValueFormat"), QStringLiteral("0123456789")}})
                .size(),
            1);
        QCOMPARE(validateSettings({{QStringLiteral("actualValueFormat"), 5}}).size(), 1);
        QCOMPARE(validateSettings({{QStringLiteral("cableLength"), QStringLiteral("10")}}).size(),
                 1);
        QCOMPARE(validateSettings({{QStringLiteral("cableLength"), 10.5}}).size(), 1);
        QVERIFY(validateSettings({{QStringLiteral("cableLength"), 10.0}}).isEmpty());
    }

    void inputReferenceRange() {
        QVERIFY(validateSettings({{QStringLiteral("presetInput"), 200}}).isEmpty());
        const QStringList problems = validateSettings({{QStringLiteral("presetInput"), 201}});
        QCOMPARE(problems.size(), 1);
        QVERIFY(problems.first().contains(QStringLiteral("0 = none")));
    }

    void unknownKeyIsReported() {
        const QStringList problems = validateSettings({{QStringLiteral("warpDrive"), 1}});
        QCOMPARE(problems.size(), 1);
        QVERIFY(problems.first().startsWith(QStringLiteral("warpDrive")));
    }

    void axisTypeDecidesRotary() {
        QVERIFY(isRotaryAxis({}));
        QVERIFY(isRotaryAxis({{QStringLiteral("axisType"), 0}}));
        QVERIFY(!isRotaryAxis({{QStringLiteral("axisType"), 1}}));
    }
};

QTEST_GUILESS_MAIN(TestSystemSettings)
#include "tst_system_settings.moc"
