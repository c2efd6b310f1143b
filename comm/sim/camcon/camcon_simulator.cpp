#include "camcon_simulator.h"

#include "sim_demo.h"
#include "sim_device.h"
#include "sim_line.h"

#include "comm/sim/sim_transport.h"

namespace cambench::comm {

namespace {

constexpr int kStandardBaud = 9600;
constexpr int kMultiuserBaud = 38400;

QString describe(const SimPortConfig& config) {
    QStringList devices;
    for (int number : config.devices) devices << QString::number(number);
    return QStringLiteral("simulator (%1, device %2, %3 baud%4)")
        .arg(config.protocolName(), devices.join(QLatin1Char(',')))
        .arg(config.baud)
        .arg(config.throttle ? QString() : QStringLiteral(", unthrottled"));
}

Result<SimPortConfig> configForPort(const QString& port, const SerialSettings& serial,
                                    const QString& protocol) {
    Result<SimPortConfig> parsed = parseSimPort(port, serial);
    if (!parsed) return parsed.error();
    SimPortConfig config = *parsed;
    // Unless the port names a framing or protocol, the simulated device
    // speaks the protocol the PC connects with.
    const bool named = config.framing || config.tableVariant;
    if (!named && (protocol != QLatin1String("standard") || config.devices.size() == 1))
        applySimProtocol(config, protocol);
    return config;
}

// The protocol the port's own keys name (protocol=, framing=): then the
// device speaks it whatever the PC speaks (configForPort).
QString namedProtocol(const QString& port) {
    const Result<SimPortConfig> config = parseSimPort(port, SerialSettings{});
    if (!config || !(config->framing || config->tableVariant)) return {};
    if (config->camBus) return QStringLiteral("cambus");
    if (config->tableVariant)
        return *config->tableVariant == table::Rk512Variant::N96 ? QStringLiteral("3964r-n96")
                                                                 : QStringLiteral("3964r-e38");
    return *config->framing == Framing::Multiuser ? QStringLiteral("multiuser")
                                                  : QStringLiteral("standard");
}

QList<QCommandLineOption> camConOptions() {
    return {
        // --device: the command line's name (a machine file's "device").
        {QStringList{QStringLiteral("devices"), QStringLiteral("device")},
         QStringLiteral("Device numbers 0..63, e.g. 0,5 (default 0)."), QStringLiteral("list")},
        {QStringLiteral("baud"),
         QStringLiteral("Baud rate for the timing (default 9600, Multiuser and 3964r-e38 "
                        "38400)."),
         QStringLiteral("rate")},
        {QStringLiteral("pc-number"),
         QStringLiteral("Multiuser: answer only this PC number (default any)."),
         QStringLiteral("n")},
        {QStringLiteral("nak"),
         QStringLiteral("3964R: probability of a NAK to a good block (not executed)."),
         QStringLiteral("p")},
        {QStringLiteral("lost-dle"),
         QStringLiteral("3964R: probability of a DLE of the device lost on the line."),
         QStringLiteral("p")},
        {QStringLiteral("collision"),
         QStringLiteral("3964R: probability of the device's STX crossing the PC's."),
         QStringLiteral("p")},
        {QStringLiteral("link-faults"),
         QStringLiteral("3964R: --corrupt (the reply's BCC), --nak, --lost-dle and --collision "
                        "at once."),
         QStringLiteral("p")},
        {QStringLiteral("fill"),
         QStringLiteral("Benchmark state: n cams on every output of every program."),
         QStringLiteral("n")},
        {QStringLiteral("users"),
         QStringLiteral("n users \"User 01\", \"User 02\", ... instead of the demo's two "
                        "(at most 32)."),
         QStringLiteral("n")},
        {QStringLiteral("display"),
         QStringLiteral("Cam-BUS: display users with these numbers, e.g. 12,13; the first polls "
                        "the first device, the second the second, ..."),
         QStringLiteral("list")},
        {QStringLiteral("pc-answer-ms"),
         QStringLiteral("Cam-BUS: how long the simulated users wait for the PC's answers "
                        "(default 10 ms as the bus's timing; more on a loaded test machine)."),
         QStringLiteral("ms")},
        {QStringLiteral("silent-after"),
         QStringLiteral("Cam-BUS: the --dead-devices answer until then (ms after the start) and "
                        "fall silent (a user that drops off the bus)."),
         QStringLiteral("ms")},
        {QStringLiteral("reinit-after"),
         QStringLiteral("Cam-BUS: a second initialisation phase this long after the start (the "
                        "first device breaks in)."),
         QStringLiteral("ms")},
        {QStringLiteral("analogue-outputs"),
         QStringLiteral("Analogue outputs 0..14 (default 14); 0: a CamCon without analogue "
                        "outputs, which refuses the analogue cam areas 241..254."),
         QStringLiteral("n")},
        {QStringLiteral("eprom"),
         QStringLiteral("Another identity: the firmware date ?EPROM answers (dd.mm.yyyy, default "
                        "11.10.1994)."),
         QStringLiteral("date")},
        {QStringLiteral("outputs"),
         QStringLiteral("Another size: this many outputs and cam tracks (1..64, default 32)."),
         QStringLiteral("n")},
        {QStringLiteral("dead-devices"),
         QStringLiteral("These devices of the line never answer, e.g. 5 (the others do)."),
         QStringLiteral("list")},
    };
}

Error optionError(const QString& text) {
    return Error::usage(text);
}

// The CamCon's own options of cambench-sim on top of the shared ones.
Result<SimulatedLine> fromOptions(const QCommandLineParser& parser, const SimHostOptions& shared) {
    SimPortConfig config;
    config.faults = shared.faults;
    config.throttle = shared.throttle;
    if (!shared.protocol.isEmpty() && !applySimProtocol(config, shared.protocol)) {
        return optionError(QStringLiteral("--protocol must be standard, multiuser, 3964r-n96, "
                                          "3964r-e38 or cambus, not \"%1\".")
                               .arg(shared.protocol));
    }
    if (parser.isSet(QStringLiteral("devices"))) {
        Result<QList<int>> devices = parseDeviceList(parser.value(QStringLiteral("devices")));
        if (!devices)
            return optionError(QStringLiteral("--devices: %1").arg(devices.error().message));
        config.devices = *devices;
    }
    if (config.tableVariant && config.devices.size() > 1)
        return optionError(QStringLiteral("3964R is point to point: one device."));
    if (!config.tableVariant && config.effectiveFraming() == Framing::Standard &&
        config.devices.size() > 1) {
        return optionError(
            QStringLiteral("Standard framing has one device; add --protocol multiuser."));
    }
    bool ok = true;
    config.baud = config.effectiveFraming() == Framing::Multiuser ? kMultiuserBaud : kStandardBaud;
    if (config.tableVariant) config.baud = table::rk512VariantInfo(*config.tableVariant).baudRate;
    if (parser.isSet(QStringLiteral("baud")))
        config.baud = parser.value(QStringLiteral("baud")).toInt(&ok);
    if (!ok || config.baud < 300)
        return optionError(QStringLiteral("--baud needs a baud rate of 300 or more."));
    std::optional<int> pcNumber;
    if (parser.isSet(QStringLiteral("pc-number"))) {
        const int pc = parser.value(QStringLiteral("pc-number")).toInt(&ok);
        if (!ok || pc < 0 || pc > 63)
            return optionError(QStringLiteral("--pc-number needs a number 0..63."));
        pcNumber = pc;
    }
    SimFaultSettings& faults = config.faults;
    const QList<std::pair<const char*, QList<double*>>> probabilities{
        {"nak", {&faults.nakProbability}},
        {"lost-dle", {&faults.lostDleProbability}},
        {"collision", {&faults.collisionProbability}},
        {"link-faults",
         {&faults.corruptProbability, &faults.nakProbability, &faults.lostDleProbability,
          &faults.collisionProbability}},
    };
    for (const auto& [name, targets] : probabilities) {
        if (!parser.isSet(QLatin1String(name))) continue;
        const auto p = parseProbability(parser.value(QLatin1String(name)));
        if (!p)
            return optionError(
                QStringLiteral("--%1 needs a probability 0..1.").arg(QLatin1String(name)));
        for (double* target : targets) *target = *p;
    }
    for (const char* name : {"fill", "users"}) {
        if (!parser.isSet(QLatin1String(name))) continue;
        const int n = parser.value(QLatin1String(name)).toInt(&ok);
        if (!ok || n < 0)
            return optionError(
                QStringLiteral("--%1 needs a whole number of 0 or more.").arg(QLatin1String(name)));
        (QByteArray(name) == "fill" ? config.fill : config.users) = n;
    }
    if (parser.isSet(QStringLiteral("display"))) {
        const Result<QList<int>> displays =
            parseDeviceList(parser.value(QStringLiteral("display")));
        bool clash = false;
        for (int number : displays ? *displays : QList<int>())
            clash |= config.devices.contains(number);
        if (!displays || clash || !config.camBus)
            return optionError(QStringLiteral(
                "--display needs --protocol cambus and user numbers 0..63 that no device has."));
        config.displays = *displays;
    }
    if (parser.isSet(QStringLiteral("pc-answer-ms"))) {
        config.pcAnswerMs = parser.value(QStringLiteral("pc-answer-ms")).toInt(&ok);
        if (!ok || config.pcAnswerMs < 1 || config.pcAnswerMs > 1000 || !config.camBus)
            return optionError(
                QStringLiteral("--pc-answer-ms needs --protocol cambus and 1..1000 ms."));
    }
    for (const char* name : {"silent-after", "reinit-after"}) {
        if (!parser.isSet(QLatin1String(name))) continue;
        const int ms = parser.value(QLatin1String(name)).toInt(&ok);
        if (!ok || ms < 0 || !config.camBus)
            return optionError(QStringLiteral("--%1 needs --protocol cambus and milliseconds.")
                                   .arg(QLatin1String(name)));
        (QByteArray(name) == "silent-after" ? config.silentAfterMs : config.reinitAfterMs) = ms;
    }
    if (parser.isSet(QStringLiteral("analogue-outputs"))) {
        config.analogueOutputs = parser.value(QStringLiteral("analogue-outputs")).toInt(&ok);
        if (!ok || config.analogueOutputs < 0 || config.analogueOutputs > 14)
            return optionError(QStringLiteral("--analogue-outputs needs a number 0..14."));
    }
    for (const char* name : {"eprom", "outputs"}) {
        if (!parser.isSet(QLatin1String(name))) continue;
        QString expected;
        const QString value = parser.value(QLatin1String(name));
        if (!(QByteArray(name) == "eprom" ? applyEpromDate(config, value, &expected)
                                          : applyOutputs(config, value, &expected)))
            return optionError(QStringLiteral("--%1 needs %2.").arg(QLatin1String(name), expected));
    }
    if (parser.isSet(QStringLiteral("dead-devices"))) {
        Result<QList<int>> dead = parseDeviceList(parser.value(QStringLiteral("dead-devices")));
        if (!dead)
            return optionError(QStringLiteral("--dead-devices: %1").arg(dead.error().message));
        config.deadDevices = *dead;
    }
    SimulatedLine line = camConSimulatedLine(config);
    if (auto* ascii = dynamic_cast<SimLine*>(line.endpoint.get())) ascii->setPcNumber(pcNumber);
    return line;
}

}  // namespace

SimulatedLine camConSimulatedLine(const SimPortConfig& config) {
    std::unique_ptr<SimCamConEndpoint> endpoint = makeSimEndpoint(config);
    SimCamConEndpoint* devices = endpoint.get();
    SimulatedLine line{std::move(endpoint),
                       SimPacer(config.baud, config.throttle, config.bitsPerByte()),
                       describe(config),
                       {}};
    // On a simulated machine the position of every CamCon of the line
    // follows the machine's shaft (issue 30).
    line.shaft.follow = [devices, numbers = config.devices](const std::shared_ptr<SimShaft>& shaft,
                                                            double perTurn) -> Status {
        for (int number : numbers)
            if (SimDevice* device = devices->device(number)) device->axis().follow(shaft, perTurn);
        return success();
    };
    return line;
}

Result<std::unique_ptr<Transport>> makeCamConSimTransport(const QString& port,
                                                          const SerialSettings& serial,
                                                          const QString& protocol) {
    Result<SimPortConfig> config = configForPort(port, serial, protocol);
    if (!config) return config.error();
    return std::unique_ptr<Transport>(std::make_unique<SimTransport>(camConSimulatedLine(*config)));
}

SimulatorInfo camconSimulator() {
    SimulatorInfo info;
    info.fromPort = [](const QString& port, const SerialSettings& serial,
                       const QString& protocol) -> Result<SimulatedLine> {
        Result<SimPortConfig> config = configForPort(port, serial, protocol);
        if (!config) return config.error();
        return camConSimulatedLine(*config);
    };
    info.options = camConOptions;
    info.fromOptions = fromOptions;
    info.namedProtocol = namedProtocol;
    return info;
}

}  // namespace cambench::comm
