#include "plan_check.h"

#include "value_text.h"

#include "model/camcon/cam_validation.h"
#include "model/camcon/data_validation.h"
#include "model/camcon/plc_file.h"

#include <QCoreApplication>
#include <QHash>
#include <QSet>

#include <algorithm>

namespace cambench::usecases {

namespace {

// The checks per kind of item, collecting into one PlanCheck.
class Checker {
public:
    Checker(const WritePlan& plan, const DeviceInfo& device, const CheckContext& context)
        : m_plan(plan), m_device(device), m_context(context) {}

    PlanCheck run() {
        checkSettings();
        for (const NameWrite& name : m_plan.programNames) checkProgramName(name);
        checkTracks();
        for (const DeadTimeWrite& deadTime : m_plan.deadTimes) checkDeadTime(deadTime);
        checkDeadTimeModes();
        for (const NameWrite& name : m_plan.outputNames) checkOutputName(name);
        checkUsers();
        for (const PlcWrite& network : m_plan.plcNetworks) checkPlcNetwork(network.wanted);
        checkTableSections();
        return m_check;
    }

private:
    void problem(const QString& text) { m_check.problems << text; }

    bool programExists(int program) {
        if (program >= 0 && program < m_device.programs) return true;
        m_check.missingPrograms.insert(program);
        return false;
    }

    bool outputExists(int output, int outputs) {
        if (output >= 1 && output <= outputs) return true;
        m_check.missingOutputs.insert(output);
        return false;
    }

    void checkSettings() {
        const std::optional<SystemSettings>& onDevice = m_plan.settingsOnDevice;
        for (const SettingsWrite& group : m_plan.settings) {
            for (auto it = group.wanted.cbegin(); it != group.wanted.cend(); ++it) {
                const SettingSpec* spec = findSetting(it.key());
                if (!spec) {
                    problem(QCoreApplication::translate("cambench::usecases",
                                                        "Setting %1: there is no such setting.")
                                .arg(it.key()));
                    continue;
                }
                // Values equal to the device's are not sent, so only the
                // others must pass: a device may hold values the manual's
                // ranges do not allow.
                const bool same = onDevice && onDevice->contains(it.key()) &&
                                  onDevice->value(it.key()).toString() == it->toString();
                if (same) continue;
                if (spec->readOnly) {
                    problem(QCoreApplication::translate(
                                "cambench::usecases",
                                "Setting %1 is read-only: the device decides it (wanted "
                                "%2%3).")
                                .arg(it.key(), it->toString(),
                                     onDevice && onDevice->contains(it.key())
                                         ? QCoreApplication::translate("cambench::usecases",
                                                                       ", the device has %1")
                                               .arg(onDevice->value(it.key()).toString())
                                         : QString()));
                    continue;
                }
                const QString why = settingValueProblem(*spec, *it);
                if (!why.isEmpty())
                    problem(QCoreApplication::translate("cambench::usecases", "Setting %1: %2.")
                                .arg(it.key(), why));
            }
        }
    }

    void checkProgramName(const NameWrite& name) {
        if (!programExists(name.number)) {
            problem(QCoreApplication::translate(
                        "cambench::usecases", "Name of program %1: the device has programs 0..%2.")
                        .arg(name.number)
                        .arg(m_device.programs - 1));
        }
        const QString why = nameProblem(name.wanted);
        if (!why.isEmpty())
            problem(QCoreApplication::translate("cambench::usecases", "Name of program %1: %2.")
                        .arg(name.number)
                        .arg(why));
    }

    void checkTracks() {
        QSet<QPair<int, int>> seen;
        QSet<int> programsReported;
        for (const TrackWrite& write : m_plan.tracks) {
            const int output = write.wanted.output;
            if (!programExists(write.program) && !programsReported.contains(write.program)) {
                programsReported.insert(write.program);
                problem(QCoreApplication::translate("cambench::usecases",
                                                    "Program %1: the device has programs 0..%2.")
                            .arg(write.program)
                            .arg(m_device.programs - 1));
            }
            if (seen.contains({write.program, output})) {
                problem(QCoreApplication::translate("cambench::usecases",
                                                    "%1: the plan holds this track twice.")
                            .arg(trackLabel(write.program, output)));
            }
            seen.insert({write.program, output});
            // A track the device has no place for: its cams need no
            // further words.
            if (!outputExists(output, m_device.outputs)) {
                problem(QCoreApplication::translate("cambench::usecases",
                                                    "%1: the device has outputs 1..%2.")
                            .arg(trackLabel(write.program, output))
                            .arg(m_device.outputs));
                continue;
            }
            if (programsReported.contains(write.program)) continue;
            for (const Cam& cam : write.wanted.cams) {
                for (const qint32 point : {cam.on, cam.off}) {
                    if (point < m_device.minPosition || point > m_device.maxPosition)
                        ++m_check.pointsOutOfRange;
                }
            }
            for (const CamProblem& camProblem :
                 validateTrack(write.wanted, write.program, m_device, m_context.rotary))
                problem(camProblem.message + QLatin1Char('.'));
        }
    }

    void checkDeadTime(const DeadTimeWrite& write) {
        if (!outputExists(write.output, m_device.deadTimeOutputs)) {
            problem(QCoreApplication::translate(
                        "cambench::usecases",
                        "Dead time of output %1: the device compensates outputs "
                        "1..%2 only.")
                        .arg(write.output)
                        .arg(m_device.deadTimeOutputs));
        }
        if (write.wanted < 0 || write.wanted > m_device.maxDeadTime) {
            problem(QCoreApplication::translate(
                        "cambench::usecases",
                        "Dead time of output %1: %2 is outside 0..%3 (0.1 ms steps).")
                        .arg(write.output)
                        .arg(write.wanted)
                        .arg(m_device.maxDeadTime));
        }
    }

    void checkDeadTimeModes() {
        for (const DeadTimeModeWrite& write : m_plan.deadTimeModes) {
            const QString why = outputDeadTimeProblem(write.output, write.wanted, m_device);
            if (!why.isEmpty()) problem(why);
            // Word 0 of the output twice in one plan, with two values.
            for (const DeadTimeWrite& deadTime : m_plan.deadTimes) {
                if (deadTime.output != write.output || deadTime.wanted == write.wanted.normal)
                    continue;
                problem(QCoreApplication::translate(
                            "cambench::usecases",
                            "Output %1: the dead time %2 and the dead time of its dead-time mode "
                            "%3 differ, but the device holds one value for both.")
                            .arg(write.output)
                            .arg(deadTimeText(deadTime.wanted), deadTimeText(write.wanted.normal)));
            }
        }
    }

    void checkTableSections() {
        QSet<int> analogueOutputs;
        for (const AnalogueCamWrite& write : m_plan.analogueCams) {
            for (const QString& why : validateAnalogueCamTrack(write.wanted, m_device))
                problem(why);
            if (analogueOutputs.contains(write.wanted.output)) {
                problem(QCoreApplication::translate("cambench::usecases",
                                                    "Analogue output %1 is to be written twice.")
                            .arg(write.wanted.output));
            }
            analogueOutputs.insert(write.wanted.output);
        }
        if (m_plan.programmingProgram) {
            for (const QString& why :
                 validateProgrammingProgram(m_plan.programmingProgram->wanted, m_device))
                problem(why);
        }
    }

    void checkOutputName(const NameWrite& name) {
        if (!outputExists(name.number, m_device.outputs)) {
            problem(QCoreApplication::translate("cambench::usecases",
                                                "Name of output %1: the device has outputs 1..%2.")
                        .arg(name.number)
                        .arg(m_device.outputs));
        }
        const QString why = nameProblem(name.wanted);
        if (!why.isEmpty())
            problem(QCoreApplication::translate("cambench::usecases", "Name of output %1: %2.")
                        .arg(name.number)
                        .arg(why));
    }

    void checkUsers() {
        if (m_plan.users.isEmpty()) return;
        // The users as the device would hold them afterwards.
        QList<User> after = m_context.usersOnDevice;
        const auto indexOf = [&after](const QString& number) {
            for (int i = 0; i < after.size(); ++i) {
                if (after.at(i).number == number) return i;
            }
            return -1;
        };
        for (const UserWrite& write : m_plan.users) {
            const QString label = userLabel(
                write.wanted ? write.wanted->name
                             : QCoreApplication::translate("cambench::usecases", "to delete"));
            const int index = write.deviceNumber.isEmpty() ? -1 : indexOf(write.deviceNumber);
            if (!write.deviceNumber.isEmpty() && index < 0) {
                problem(QCoreApplication::translate(
                            "cambench::usecases",
                            "%1: the device has no user with the number given for "
                            "it; read the users again.")
                            .arg(label));
                continue;
            }
            if (!write.wanted) {
                after.removeAt(index);
                continue;
            }
            if (write.wanted->number.isEmpty()) {
                problem(QCoreApplication::translate(
                            "cambench::usecases",
                            "%1 has no number and the device has no user of that "
                            "name whose number it could keep; enter a number.")
                            .arg(label));
                continue;
            }
            const QString why = userProblem(*write.wanted);
            if (!why.isEmpty()) problem(QStringLiteral("%1: %2.").arg(label, why));
            if (index >= 0)
                after[index] = *write.wanted;
            else
                after.append(*write.wanted);
        }
        QHash<QString, QString> firstWithNumber;
        for (const User& user : after) {
            if (user.number.isEmpty()) continue;
            const auto first = firstWithNumber.constFind(user.number);
            if (first != firstWithNumber.cend()) {
                problem(QCoreApplication::translate(
                            "cambench::usecases",
                            "%1 would have the same user number as %2; numbers must "
                            "be unique.")
                            .arg(userLabel(user.name), userLabel(*first)));
            } else {
                firstWithNumber.insert(user.number, user.name);
            }
        }
    }

    void checkPlcNetwork(const PlcNetwork& network) {
        for (const QString& why : validatePlcNetwork(network))
            problem(QStringLiteral("%1: %2").arg(plcLabel(network), why));
        const auto count = m_context.plcNetworksPerArea.constFind(network.area);
        if (count != m_context.plcNetworksPerArea.cend() && network.number >= *count) {
            problem(QCoreApplication::translate(
                        "cambench::usecases",
                        "%1: the device has %2 networks in area %3 (%3%4); change the PLC "
                        "counts in the settings first.")
                        .arg(plcLabel(network))
                        .arg(*count)
                        .arg(plcAreaLetter(network.area))
                        .arg(*count > 0 ? QStringLiteral("0..%1").arg(*count - 1) : QString()));
        }
    }

    const WritePlan& m_plan;
    const DeviceInfo& m_device;
    const CheckContext& m_context;
    PlanCheck m_check;
};

}  // namespace

Error PlanCheck::refusal(const DeviceInfo& device, int listed) const {
    QStringList reasons;
    if (!missingOutputs.isEmpty()) {
        reasons << QCoreApplication::translate(
                       "cambench::usecases", "outputs %1 do not exist on the device (it has 1..%2)")
                       .arg(numberRanges(missingOutputs))
                       .arg(device.outputs);
    }
    if (!missingPrograms.isEmpty()) {
        reasons << QCoreApplication::translate(
                       "cambench::usecases",
                       "programs %1 do not exist on the device (it has 0..%2)")
                       .arg(numberRanges(missingPrograms))
                       .arg(device.programs - 1);
    }
    if (pointsOutOfRange > 0) {
        reasons << QCoreApplication::translate(
                       "cambench::usecases", "%1 cam points lie outside the device's range %2..%3")
                       .arg(pointsOutOfRange)
                       .arg(device.minPosition)
                       .arg(device.maxPosition);
    }
    if (reasons.isEmpty())
        reasons << QCoreApplication::translate("cambench::usecases",
                                               "the plan holds invalid values");
    QString message =
        QCoreApplication::translate("cambench::usecases",
                                    "The write was refused before anything was sent: %1 (%2):")
            .arg(reasons.join(QLatin1String("; ")),
                 problems.size() == 1
                     ? QCoreApplication::translate("cambench::usecases", "1 problem")
                     : QCoreApplication::translate("cambench::usecases", "%1 problems")
                           .arg(problems.size()));
    for (int i = 0; i < problems.size() && i < listed; ++i)
        message += QStringLiteral("\n  ") + problems.at(i);
    if (problems.size() > listed)
        message += QCoreApplication::translate("cambench::usecases", "\n  and %1 more")
                       .arg(problems.size() - listed);
    return Error::invalidData(message);
}

PlanCheck checkPlan(const WritePlan& plan, const DeviceInfo& device, const CheckContext& context) {
    return Checker(plan, device, context).run();
}

QString numberRanges(const QSet<int>& numbers) {
    QList<int> sorted = numbers.values();
    std::sort(sorted.begin(), sorted.end());
    QStringList parts;
    for (int i = 0; i < sorted.size();) {
        int j = i;
        while (j + 1 < sorted.size() && sorted.at(j + 1) == sorted.at(j) + 1) ++j;
        parts << (j == i ? QString::number(sorted.at(i))
                         : QStringLiteral("%1..%2").arg(sorted.at(i)).arg(sorted.at(j)));
        i = j + 1;
    }
    return parts.join(QLatin1String(", "));
}

}  // namespace cambench::usecases
