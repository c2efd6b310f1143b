#include "sim_port_config.h"

#include <QRegularExpression>
#include <QStringList>

namespace cambench::comm {

namespace {

const QString kPrefix = QStringLiteral("sim");
const QString kKeys = QStringLiteral(
    "devices, display, pcanswer, framing, protocol, baud, corrupt, drop, ignore, dropfirst, nak, "
    "lostdle, collision, "
    "linkfaults, "
    "delay, seed, throttle, fill, users, analogue, dead, eprom, outputs");

// The probabilities a key sets.
QList<double*> probabilitiesOf(SimFaultSettings& faults, const QString& key) {
    if (key == QLatin1String("corrupt")) return {&faults.corruptProbability};
    if (key == QLatin1String("drop")) return {&faults.dropProbability};
    if (key == QLatin1String("ignore")) return {&faults.ignoreProbability};
    if (key == QLatin1String("nak")) return {&faults.nakProbability};
    if (key == QLatin1String("lostdle")) return {&faults.lostDleProbability};
    if (key == QLatin1String("collision")) return {&faults.collisionProbability};
    if (key == QLatin1String("linkfaults"))
        return {&faults.corruptProbability, &faults.nakProbability, &faults.lostDleProbability,
                &faults.collisionProbability};
    return {};
}

Error badValue(const QString& port, const QString& key, const QString& value,
               const QString& expected) {
    return Error::usage(QStringLiteral("Simulator port \"%1\": %2=%3 is not valid; expected %4.")
                            .arg(port, key, value, expected));
}

// Parses one key; empty on success, else the error.
std::optional<Error> applyKey(SimPortConfig& config, const QString& port, const QString& key,
                              const QString& value) {
    bool ok = false;
    if (key == QLatin1String("devices")) {
        Result<QList<int>> devices = parseDeviceList(value);
        if (!devices)
            return Error::usage(
                QStringLiteral("Simulator port \"%1\": %2").arg(port, devices.error().message));
        config.devices = *devices;
    } else if (key == QLatin1String("display")) {
        Result<QList<int>> displays = parseDeviceList(value);
        if (!displays) return badValue(port, key, value, QStringLiteral("user numbers 0..63"));
        config.displays = *displays;
    } else if (key == QLatin1String("pcanswer")) {
        config.pcAnswerMs = value.toInt(&ok);
        if (!ok || config.pcAnswerMs < 1 || config.pcAnswerMs > 1000)
            return badValue(port, key, value, QStringLiteral("milliseconds 1..1000"));
    } else if (key == QLatin1String("framing")) {
        if (value == QLatin1String("standard")) {
            config.framing = Framing::Standard;
        } else if (value == QLatin1String("multiuser")) {
            config.framing = Framing::Multiuser;
        } else {
            return badValue(port, key, value, QStringLiteral("standard or multiuser"));
        }
    } else if (key == QLatin1String("protocol")) {
        if (!applySimProtocol(config, value)) {
            return badValue(port, key, value,
                            QStringLiteral("standard, multiuser, 3964r-n96, 3964r-e38 or cambus"));
        }
    } else if (key == QLatin1String("baud")) {
        config.baud = value.toInt(&ok);
        if (!ok || config.baud < 300)
            return badValue(port, key, value, QStringLiteral("a baud rate of 300 or more"));
    } else if (const QList<double*> targets = probabilitiesOf(config.faults, key);
               !targets.isEmpty()) {
        const double p = value.toDouble(&ok);
        if (!ok || p < 0.0 || p > 1.0)
            return badValue(port, key, value, QStringLiteral("a probability 0..1"));
        for (double* target : targets) *target = p;
    } else if (key == QLatin1String("dropfirst")) {
        if (value.size() < 2 || (value.at(0) != u'?' && value.at(0) != u'!'))
            return badValue(port, key, value, QStringLiteral("a request start such as !EE0000"));
        config.faults.dropFirstReplyTo = value.toLatin1();
    } else if (key == QLatin1String("delay") || key == QLatin1String("fill") ||
               key == QLatin1String("users")) {
        const int n = value.toInt(&ok);
        if (!ok || n < 0)
            return badValue(port, key, value, QStringLiteral("a whole number of 0 or more"));
        (key == QLatin1String("delay")  ? config.faults.extraDelayMs
         : key == QLatin1String("fill") ? config.fill
                                        : config.users) = n;
    } else if (key == QLatin1String("analogue")) {
        config.analogueOutputs = value.toInt(&ok);
        if (!ok || config.analogueOutputs < 0 || config.analogueOutputs > 14)
            return badValue(port, key, value, QStringLiteral("analogue outputs 0..14"));
    } else if (key == QLatin1String("eprom") || key == QLatin1String("outputs")) {
        QString expected;
        if (!(key == QLatin1String("eprom") ? applyEpromDate(config, value, &expected)
                                            : applyOutputs(config, value, &expected)))
            return badValue(port, key, value, expected);
    } else if (key == QLatin1String("seed")) {
        config.faults.seed = value.toUInt(&ok);
        if (!ok) return badValue(port, key, value, QStringLiteral("a whole number"));
    } else if (key == QLatin1String("throttle") || key == QLatin1String("dead")) {
        if (value != QLatin1String("0") && value != QLatin1String("1")) {
            return badValue(port, key, value, QStringLiteral("0 or 1"));
        }
        (key == QLatin1String("throttle") ? config.throttle : config.faults.dead) =
            value == QLatin1String("1");
    } else {
        return Error::usage(
            QStringLiteral("Simulator port \"%1\": unknown key \"%2\"; use one of %3.")
                .arg(port, key, kKeys));
    }
    return std::nullopt;
}

}  // namespace

int SimPortConfig::bitsPerByte() const {
    if (!tableVariant) return 10;
    return table::rk512VariantInfo(*tableVariant).parity == 'N' ? 10 : 11;
}

QString SimPortConfig::protocolName() const {
    if (camBus) return QStringLiteral("Cam-BUS");
    if (tableVariant) return QLatin1String(table::rk512VariantInfo(*tableVariant).name);
    return effectiveFraming() == Framing::Multiuser ? QStringLiteral("Multiuser")
                                                    : QStringLiteral("Standard");
}

bool applySimProtocol(SimPortConfig& config, const QString& protocol) {
    config.camBus = false;
    if (protocol == QLatin1String("cambus")) {
        config.camBus = true;
        config.framing = Framing::Multiuser;  // several devices, each with its number
        config.tableVariant.reset();
    } else if (protocol == QLatin1String("standard") || protocol == QLatin1String("multiuser")) {
        config.framing =
            protocol == QLatin1String("multiuser") ? Framing::Multiuser : Framing::Standard;
        config.tableVariant.reset();
    } else if (protocol == QLatin1String("3964r-n96")) {
        config.tableVariant = table::Rk512Variant::N96;
    } else if (protocol == QLatin1String("3964r-e38")) {
        config.tableVariant = table::Rk512Variant::E38;
    } else {
        return false;
    }
    return true;
}

bool applyEpromDate(SimPortConfig& config, const QString& date, QString* expected) {
    // The form ?EPROM answers (the manual's example 11.10.1994).
    static const QRegularExpression form(QStringLiteral("^\\d\\d\\.\\d\\d\\.\\d{4}$"));
    if (!form.match(date).hasMatch()) {
        *expected = QStringLiteral("a firmware date dd.mm.yyyy such as 03.05.2001");
        return false;
    }
    config.epromDate = date.toLatin1();
    return true;
}

bool applyOutputs(SimPortConfig& config, const QString& outputs, QString* expected) {
    bool ok = false;
    const int n = outputs.toInt(&ok);
    if (!ok || n < 1 || n > 64) {
        *expected = QStringLiteral("outputs 1..64");
        return false;
    }
    config.outputs = n;
    return true;
}

Result<QList<int>> parseDeviceList(const QString& text) {
    QList<int> devices;
    for (const QString& part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        bool ok = false;
        const int number = part.trimmed().toInt(&ok);
        if (!ok || number < 0 || number > 63) {
            return Error::usage(QStringLiteral("device number \"%1\" is not 0..63.").arg(part));
        }
        if (devices.contains(number))
            return Error::usage(QStringLiteral("device %1 is listed twice.").arg(number));
        devices.append(number);
    }
    if (devices.isEmpty())
        return Error::usage(QStringLiteral("no device numbers in \"%1\".").arg(text));
    return devices;
}

Result<SimPortConfig> parseSimPort(const QString& port, const SerialSettings& serial) {
    if (!isSimPort(port)) {
        return Error::usage(
            QStringLiteral("\"%1\" is not a simulator port; use sim or sim:key=value;...")
                .arg(port));
    }
    SimPortConfig config;
    config.baud = serial.baud;
    const QString options = port.mid(kPrefix.size() + 1);
    for (const QString& item : options.split(QLatin1Char(';'), Qt::SkipEmptyParts)) {
        const qsizetype eq = item.indexOf(QLatin1Char('='));
        if (eq <= 0) {
            return Error::usage(
                QStringLiteral("Simulator port \"%1\": \"%2\" is not key=value; use one of %3.")
                    .arg(port, item, kKeys));
        }
        if (auto error =
                applyKey(config, port, item.left(eq).trimmed(), item.mid(eq + 1).trimmed())) {
            return *error;
        }
    }
    if (config.effectiveFraming() == Framing::Standard && config.devices.size() > 1) {
        return Error::usage(
            QStringLiteral("Simulator port \"%1\": Standard framing has one device; "
                           "use framing=multiuser for several.")
                .arg(port));
    }
    if (config.tableVariant && config.devices.size() > 1) {
        return Error::usage(
            QStringLiteral("Simulator port \"%1\": 3964R is point to point, one device.")
                .arg(port));
    }
    return config;
}

}  // namespace cambench::comm
