#include "mc1_simulator.h"

#include "sim_mc1_ascii_line.h"
#include "sim_mc1_line.h"

#include "comm/mc1/mc1_address.h"
#include "comm/mc1/mc1_device.h"

namespace cambench::comm {

namespace {

constexpr Mc1Variant kDefaultVariant = Mc1Variant::Mc200V2;
constexpr int kDefaultBaud = 9600;

QString variantList() {
    QStringList keys;
    for (Mc1Variant variant : allMc1Variants()) keys << mc1VariantKey(variant);
    return keys.join(QStringLiteral(", "));
}

Result<Mc1Variant> variantFrom(const QString& text) {
    if (const std::optional<Mc1Variant> variant = mc1VariantFromKey(text.trimmed().toLower()))
        return *variant;
    return Error::usage(
        QStringLiteral("the variant must be one of %1, not \"%2\"").arg(variantList(), text));
}

// Something to look at: V1..V10, a few flags and outputs.
void addDemoState(SimMc1Controller& controller) {
    for (int n = 1; n <= 10; ++n) controller.setVariable(n, n * 100 - 350);
    const bool mc200 = isMc200(controller.variant());
    for (const char* point : {"M1", "M5", "M2327", "A1", "A3", "E2"}) {
        const Result<Mc1Point> parsed = parseMc1Point(QLatin1String(point));
        const Result<Mc1BitAddress> address = mc1BitAddress(*parsed, mc200);
        if (address) controller.setBit(*address, true);
    }
}

// --sync / sync=: 5 or 10 ms, on an MC100 V1 only (single-FIFO cards).
Result<int> syncFrom(const QString& text, Mc1Variant variant) {
    const int ms = text.toInt();
    if (ms != 5 && ms != 10)
        return Error::usage(QStringLiteral("sync must be 5 or 10 (ms), not \"%1\"").arg(text));
    if (variant != Mc1Variant::Mc100V1)
        return Error::usage(
            QStringLiteral("sync is for the MC100MA's single-FIFO cards, an "
                           "MC100 V1: add --variant mc100v1"));
    return ms;
}

const QLatin1String kAsciiProtocol("mc1-ascii");

// axes= / --axes: the logical axes the simulated MC200 has.
Status axesFrom(const QString& text, Mc1SimAxes& axes) {
    const Result<QList<int>> parsed = parseMc1AxisList(text);
    if (!parsed) return parsed.error();
    axes.axes = *parsed;
    return success();
}

// parameters= / --parameter-base: where its axis parameters start.
Status parameterBaseFrom(const QString& text, Mc1SimAxes& axes) {
    bool ok = false;
    const uint base = text.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)
                          ? text.mid(2).toUInt(&ok, 16)
                          : text.toUInt(&ok, 10);
    if (!ok || base + 0x10 * kMc1LastAxis + 2 > 0xFFFF)
        return Error::usage(
            QStringLiteral("the parameter base must be a number below 0xFF00, not \"%1\"")
                .arg(text));
    axes.parameterBase = quint16(base);
    return success();
}

// udb= / --udb: where its PLC program's data block starts.
Status udbFrom(const QString& text, Mc1SimAxes& axes) {
    bool ok = false;
    const uint address = text.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)
                             ? text.mid(2).toUInt(&ok, 16)
                             : text.toUInt(&ok, 10);
    if (!ok)
        return Error::usage(
            QStringLiteral("the UDB address must be a number such as 0x12000, not \"%1\"")
                .arg(text));
    axes.udbAddress = quint32(address);
    return success();
}

// The ASCII protocol is the MC100's (V1 and V2 alike), without the
// single-FIFO synchronisation.
Status checkAscii(Mc1Variant variant, int syncMs) {
    if (isMc200(variant) && variant != kDefaultVariant)
        return Error::usage(QStringLiteral("the ASCII protocol is the MC100's, not the %1's")
                                .arg(mc1VariantName(variant)));
    if (syncMs) return Error::usage(QStringLiteral("the ASCII protocol has no 0xFF sync"));
    return success();
}

}  // namespace

SimulatedLine mc1AsciiSimulatedLine(int baud, const SimHostOptions& shared) {
    auto line = std::make_unique<SimMc1AsciiLine>(shared.faults);
    addDemoState(line->controller());
    return {std::move(line), SimPacer(baud, shared.throttle, 10),
            QStringLiteral("simulator (MC100, ASCII protocol, %1 baud%2)")
                .arg(baud)
                .arg(shared.throttle ? QString() : QStringLiteral(", unthrottled"))};
}

SimulatedLine mc1SimulatedLine(Mc1Variant variant, int baud, const SimHostOptions& shared,
                               int syncMs, const Mc1SimAxes& axes) {
    auto line = std::make_unique<SimMc1Line>(variant, shared.faults);
    line->setSync(syncMs);
    if (axes.axes) line->controller().setAxes(*axes.axes);
    if (axes.parameterBase)
        line->controller().setAxisParameters(mc1AxisParametersFrom(
            *axes.parameterBase, QStringLiteral("the simulated controller's own")));
    if (axes.udbAddress) line->controller().setUdbAddress(*axes.udbAddress);
    addDemoState(line->controller());
    SimMc1Line* drivesShaft = line.get();
    const QString description =
        QStringLiteral("simulator (%1, %2 baud%3)")
            .arg(mc1VariantName(variant))
            .arg(baud)
            .arg(shared.throttle ? QString() : QStringLiteral(", unthrottled"))
            .append(syncMs ? QStringLiteral(", 0xFF every %1 ms").arg(syncMs) : QString());
    SimulatedLine simulated{std::move(line), SimPacer(baud, shared.throttle, 10), description, {}};
    // On a simulated machine one of its axes drives the shaft (issue 30).
    simulated.shaft.drive = [drivesShaft](const std::shared_ptr<SimShaft>& shaft, int axis) {
        return drivesShaft->driveShaft(shaft, axis);
    };
    return simulated;
}

SimulatorInfo mc1Simulator() {
    SimulatorInfo info;
    // "sim" or "sim:variant=mc100v1": the in-process simulator.
    info.fromPort = [](const QString& port, const SerialSettings& serial,
                       const QString& protocol) -> Result<SimulatedLine> {
        Mc1Variant variant = kDefaultVariant;
        QString sync;
        Mc1SimAxes axes;
        const QString options = port.section(QLatin1Char(':'), 1);
        for (const QString& option : options.split(QLatin1Char(';'), Qt::SkipEmptyParts)) {
            const QString key = option.section(QLatin1Char('='), 0, 0).trimmed();
            const QString value = option.section(QLatin1Char('='), 1);
            if (key == QLatin1String("sync")) {
                sync = value;
                continue;
            }
            if (key == QLatin1String("axes") || key == QLatin1String("parameters") ||
                key == QLatin1String("udb")) {
                const Status ok = key == QLatin1String("axes") ? axesFrom(value, axes)
                                  : key == QLatin1String("parameters")
                                      ? parameterBaseFrom(value, axes)
                                      : udbFrom(value, axes);
                if (!ok) return ok.error();
                continue;
            }
            if (key != QLatin1String("variant"))
                return Error::usage(
                    QStringLiteral("the MC-1 simulator's port takes variant=…, sync=…, axes=…, "
                                   "parameters=… and udb=…, not \"%1\"")
                        .arg(option));
            const Result<Mc1Variant> parsed = variantFrom(value);
            if (!parsed) return parsed.error();
            variant = *parsed;
        }
        int syncMs = 0;
        if (!sync.isEmpty()) {
            const Result<int> parsed = syncFrom(sync, variant);
            if (!parsed) return parsed.error();
            syncMs = *parsed;
        }
        SimHostOptions shared;
        shared.throttle = false;
        if (protocol == kAsciiProtocol) {
            if (const Status ascii = checkAscii(variant, syncMs); !ascii) return ascii.error();
            return mc1AsciiSimulatedLine(serial.baud, shared);
        }
        return mc1SimulatedLine(variant, serial.baud, shared, syncMs, axes);
    };
    info.options = [] {
        return QList<QCommandLineOption>{
            {QStringLiteral("variant"),
             QStringLiteral("MC-1: the controller, one of %1 (default %2).")
                 .arg(variantList(), mc1VariantKey(kDefaultVariant)),
             QStringLiteral("variant")},
            {QStringLiteral("baud"),
             QStringLiteral("Baud rate for the timing (default %1).").arg(kDefaultBaud),
             QStringLiteral("rate")},
            {QStringLiteral("sync"),
             QStringLiteral("MC-1, MC100 V1: an MC100MA single-FIFO card sending 0xFF every 5 or "
                            "10 ms; telegrams outside the window after one are lost."),
             QStringLiteral("ms")},
            {QStringLiteral("axes"),
             QStringLiteral("MC-1, MC200: the logical axes it has, e.g. 1,3 (default 1-8); "
                            "commands for others are refused."),
             QStringLiteral("list")},
            {QStringLiteral("parameter-base"),
             QStringLiteral("MC-1, MC200: its axis parameters are base + 0x10 x axis + 0 "
                            "(position), 1 (target), 2 (status); default 0x1000, CamBench's "
                            "built-in guess."),
             QStringLiteral("number")},
            {QStringLiteral("udb"),
             QStringLiteral("MC-1, MC200 V2: where its PLC program's data block starts (SYSDATA "
                            "08; default 0x10000); another program, another address."),
             QStringLiteral("address")},
        };
    };
    info.fromOptions = [](const QCommandLineParser& parser,
                          const SimHostOptions& shared) -> Result<SimulatedLine> {
        Mc1Variant variant = kDefaultVariant;
        if (parser.isSet(QStringLiteral("variant"))) {
            const Result<Mc1Variant> parsed = variantFrom(parser.value(QStringLiteral("variant")));
            if (!parsed)
                return Error::usage(QStringLiteral("--variant: %1").arg(parsed.error().message));
            variant = *parsed;
        }
        int baud = kDefaultBaud;
        if (parser.isSet(QStringLiteral("baud"))) {
            bool ok = false;
            baud = parser.value(QStringLiteral("baud")).toInt(&ok);
            if (!ok || baud < 300)
                return Error::usage(QStringLiteral("--baud needs a baud rate of 300 or more."));
        }
        int syncMs = 0;
        if (parser.isSet(QStringLiteral("sync"))) {
            const Result<int> parsed = syncFrom(parser.value(QStringLiteral("sync")), variant);
            if (!parsed) return Error::usage(QStringLiteral("--%1").arg(parsed.error().message));
            syncMs = *parsed;
        }
        Mc1SimAxes axes;
        if (parser.isSet(QStringLiteral("axes")))
            if (const Status ok = axesFrom(parser.value(QStringLiteral("axes")), axes); !ok)
                return Error::usage(QStringLiteral("--axes: %1").arg(ok.error().message));
        if (parser.isSet(QStringLiteral("parameter-base")))
            if (const Status ok =
                    parameterBaseFrom(parser.value(QStringLiteral("parameter-base")), axes);
                !ok)
                return Error::usage(QStringLiteral("--parameter-base: %1").arg(ok.error().message));
        if (parser.isSet(QStringLiteral("udb")))
            if (const Status ok = udbFrom(parser.value(QStringLiteral("udb")), axes); !ok)
                return Error::usage(QStringLiteral("--udb: %1").arg(ok.error().message));
        if (shared.protocol == kAsciiProtocol) {
            if (const Status ascii = checkAscii(variant, syncMs); !ascii)
                return Error::usage(
                    QStringLiteral("--protocol mc1-ascii: %1").arg(ascii.error().message));
            return mc1AsciiSimulatedLine(baud, shared);
        }
        return mc1SimulatedLine(variant, baud, shared, syncMs, axes);
    };
    return info;
}

}  // namespace cambench::comm
