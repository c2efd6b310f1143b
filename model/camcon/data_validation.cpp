#include "data_validation.h"

#include <QHash>
#include <QSet>

#include <algorithm>

namespace cambench {

namespace {

// Outputs the device's access table can address (32 bytes of bits).
constexpr int kUserAccessOutputs = 256;

QString quoted(const QString& name) {
    return QLatin1Char('"') + name + QLatin1Char('"');
}

bool isPrintableAscii(QChar c) {
    return c.unicode() >= 0x20 && c.unicode() <= 0x7E;
}

}  // namespace

QString nameProblem(const QString& name) {
    if (name.size() > kMaxNameLength) {
        return QStringLiteral("%1 has %2 characters; the device stores at most %3")
            .arg(quoted(name))
            .arg(name.size())
            .arg(kMaxNameLength);
    }
    for (const QChar c : name) {
        if (c.unicode() > 0xFF) {
            return QStringLiteral(
                       "%1 contains '%2', which the device cannot show (only "
                       "Latin-1 characters are possible)")
                .arg(quoted(name), c);
        }
        if (c.unicode() < 0x20 || (c.unicode() >= 0x7F && c.unicode() < 0xA0)) {
            return QStringLiteral("%1 contains the control character 0x%2")
                .arg(quoted(name))
                .arg(c.unicode(), 2, 16, QLatin1Char('0'));
        }
    }
    return {};
}

QStringList validateDeadTimes(const DeadTimes& deadTimes, const DeviceInfo& device) {
    QStringList problems;
    for (auto it = deadTimes.cbegin(); it != deadTimes.cend(); ++it) {
        if (it.key() < 1 || it.key() > device.deadTimeOutputs) {
            problems << QStringLiteral(
                            "Dead time of output %1: the device compensates outputs "
                            "1..%2 only.")
                            .arg(it.key())
                            .arg(device.deadTimeOutputs);
        }
        if (*it < 0 || *it > device.maxDeadTime) {
            problems << QStringLiteral(
                            "Dead time of output %1: %2 is outside 0..%3 "
                            "(0.1 ms steps).")
                            .arg(it.key())
                            .arg(*it)
                            .arg(device.maxDeadTime);
        }
    }
    return problems;
}

QStringList validateNames(const Names& names, const DeviceInfo& device) {
    QStringList problems;
    for (auto it = names.outputs.cbegin(); it != names.outputs.cend(); ++it) {
        if (it.key() < 1 || it.key() > device.outputs) {
            problems << QStringLiteral("Name of output %1: the device has outputs 1..%2.")
                            .arg(it.key())
                            .arg(device.outputs);
        }
        const QString problem = nameProblem(*it);
        if (!problem.isEmpty())
            problems << QStringLiteral("Name of output %1: %2.").arg(it.key()).arg(problem);
    }
    for (auto it = names.programs.cbegin(); it != names.programs.cend(); ++it) {
        if (it.key() < 0 || it.key() >= device.programs) {
            problems << QStringLiteral("Name of program %1: the device has programs 0..%2.")
                            .arg(it.key())
                            .arg(device.programs - 1);
        }
        const QString problem = nameProblem(*it);
        if (!problem.isEmpty())
            problems << QStringLiteral("Name of program %1: %2.").arg(it.key()).arg(problem);
    }
    return problems;
}

QString userProblem(const User& user, UserNumbers numbers) {
    const QString name = nameProblem(user.name);
    if (!name.isEmpty()) return QStringLiteral("the name %1").arg(name);
    const bool mayLackNumber = numbers == UserNumbers::Optional && user.number.isEmpty();
    if (!mayLackNumber && (user.number.isEmpty() || user.number.size() > kMaxUserNumberLength))
        return QStringLiteral("the user number must have 1 to %1 characters")
            .arg(kMaxUserNumberLength);
    if (!std::all_of(user.number.cbegin(), user.number.cend(), isPrintableAscii))
        return QStringLiteral("the user number may hold only printable ASCII characters");
    if (user.number == QLatin1String("DEL"))
        return QStringLiteral("the user number \"DEL\" is reserved: it deletes a user");
    if (user.outputAccess.size() > kUserAccessOutputs)
        return QStringLiteral("%1 output access entries, but the device has %2")
            .arg(user.outputAccess.size())
            .arg(kUserAccessOutputs);
    return {};
}

QStringList validateUsers(const QList<User>& users, UserNumbers numbers) {
    QStringList problems;
    QHash<QString, int> firstWithNumber;
    for (int i = 0; i < users.size(); ++i) {
        const User& user = users.at(i);
        const QString label = QStringLiteral("User %1 (%2)").arg(i + 1).arg(quoted(user.name));
        const QString problem = userProblem(user, numbers);
        if (!problem.isEmpty()) problems << QStringLiteral("%1: %2.").arg(label, problem);
        if (user.number.isEmpty()) continue;
        const auto first = firstWithNumber.constFind(user.number);
        if (first != firstWithNumber.cend()) {
            problems << QStringLiteral(
                            "%1 has the same user number as user %2; numbers must "
                            "be unique.")
                            .arg(label)
                            .arg(*first + 1);
        } else {
            firstWithNumber.insert(user.number, i);
        }
    }
    return problems;
}

QStringList validatePlcNetwork(const PlcNetwork& network) {
    QStringList problems;
    static const QSet<int> areas = {PlcNetwork::O, PlcNetwork::P, PlcNetwork::M, PlcNetwork::X};
    if (!areas.contains(network.area)) {
        problems << QStringLiteral(
                        "PLC network area 0x%1 is unknown; allowed are 0x08 (O), "
                        "0x09 (P), 0x0A (M) and 0x0B (X).")
                        .arg(network.area, 2, 16, QLatin1Char('0'));
    }
    if (network.number < 0 || network.number > kMaxPlcNumber) {
        problems << QStringLiteral("PLC network number %1 is outside 0..%2.")
                        .arg(network.number)
                        .arg(kMaxPlcNumber);
    }
    return problems;
}

}  // namespace cambench
