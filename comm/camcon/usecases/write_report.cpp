#include "write_report.h"

namespace cambench::usecases {

QList<OutcomeLine> WriteReport::lines() const {
    QList<OutcomeLine> lines;
    const auto add = [&lines](const auto& outcomes) {
        for (const auto& outcome : outcomes) lines.append(outcomeLine(outcome));
    };
    const auto addOne = [&lines](const auto& outcome) {
        if (outcome) lines.append(outcomeLine(*outcome));
    };
    // An unlock is written first, a lock last (WritePlan).
    const bool unlockFirst = eepromLockFirst;
    if (unlockFirst) addOne(eepromLock);
    add(settings);
    add(programNames);
    add(tracks);
    add(deadTimes);
    add(deadTimeModes);
    add(outputNames);
    add(users);
    add(plcNetworks);
    add(analogueCams);
    addOne(programmingProgram);
    if (!unlockFirst) addOne(eepromLock);
    add(linkSettings);
    return lines;
}

QString WriteReport::summary() const {
    QString text = tally().summary();
    for (const QString& note : notes) text += QLatin1Char('\n') + note;
    return text;
}

}  // namespace cambench::usecases
