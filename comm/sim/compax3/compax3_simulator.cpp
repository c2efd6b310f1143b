#include "compax3_simulator.h"

#include "sim_compax3_line.h"

#include "comm/compax3/compax3_syntax.h"

namespace cambench::comm {

namespace {

constexpr int kDefaultBaud = 115200;
constexpr int kDefaultAddress = 1;
const QLatin1String kRs485Protocol("compax3-rs485");
const QLatin1String kDefaultType("S025V2");

struct DriveOptions {
    int address = -1;  // -1: RS232
    QString type = kDefaultType;
    QString serial;  // empty: the simulated drive's own (C3-4711-0815)
    int baud = kDefaultBaud;
    QList<Compax3ObjectId> lacks;    // a firmware without these objects
    QList<Compax3ObjectId> refuses;  // reads answered !0005
    int delayMs = 0;                 // a sim: port's delay=…: every answer that late
};

Result<int> addressFrom(const QString& text) {
    bool ok = false;
    const int address = text.toInt(&ok);
    if (!ok || address < 0 || address > kCompax3LastAddress)
        return Error::usage(QStringLiteral("address must be 0..99, not \"%1\"").arg(text));
    return address;
}

SimulatedLine lineFor(const DriveOptions& options, const SimHostOptions& shared) {
    SimCompax3Drive drive = options.serial.isEmpty()
                                ? SimCompax3Drive(options.type)
                                : SimCompax3Drive(options.type, options.serial);
    for (const Compax3ObjectId& id : options.lacks) drive.removeObject(id);
    for (const Compax3ObjectId& id : options.refuses) drive.refuseReads(id);
    auto line = std::make_unique<SimCompax3Line>(options.address, std::move(drive), shared.faults);
    SimCompax3Line* drivesShaft = line.get();
    const QString where = options.address < 0
                              ? QStringLiteral("RS232")
                              : QStringLiteral("RS485 address %1").arg(options.address);
    SimulatedLine simulated{std::move(line),
                            SimPacer(options.baud, shared.throttle, 10),
                            QStringLiteral("simulator (Compax3 %1, %2, %3 baud%4)")
                                .arg(options.type, where)
                                .arg(options.baud)
                                .arg(shared.throttle ? QString() : QStringLiteral(", unthrottled")),
                            {}};
    // On a simulated machine its one axis drives the shaft (issue 30).
    simulated.shaft.drive = [drivesShaft](const std::shared_ptr<SimShaft>& shaft,
                                          int axis) -> Status {
        if (axis != 1)
            return Error::usage(
                QStringLiteral("a Compax3 has one axis; the shaft's axis must be 1, not %1")
                    .arg(axis));
        drivesShaft->driveShaft(shaft);
        return success();
    };
    return simulated;
}

}  // namespace

SimulatorInfo compax3Simulator() {
    SimulatorInfo info;
    info.fromPort = [](const QString& port, const SerialSettings& serial,
                       const QString& protocol) -> Result<SimulatedLine> {
        DriveOptions options;
        options.baud = serial.baud;
        if (protocol == kRs485Protocol) options.address = kDefaultAddress;
        const QString list = port.section(QLatin1Char(':'), 1);
        for (const QString& option : list.split(QLatin1Char(';'), Qt::SkipEmptyParts)) {
            const QString key = option.section(QLatin1Char('='), 0, 0).trimmed();
            const QString value = option.section(QLatin1Char('='), 1).trimmed();
            if (key == QLatin1String("type") && !value.isEmpty()) {
                options.type = value;
            } else if (key == QLatin1String("serial") && !value.isEmpty()) {
                options.serial = value;
            } else if (key == QLatin1String("lacks") || key == QLatin1String("refuse")) {
                // "sim:lacks=1901.0,1902.0": a drive whose firmware lacks
                // them; "refuse=1000.3": reads of it answer !0005.
                QList<Compax3ObjectId>& into =
                    key == QLatin1String("lacks") ? options.lacks : options.refuses;
                for (const QString& object : value.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
                    const Result<Compax3ObjectId> id = parseCompax3Object(object);
                    if (!id) return id.error();
                    into << *id;
                }
            } else if (key == QLatin1String("delay")) {
                // "sim:delay=400": every answer 400 ms late (cambench-sim --delay).
                bool ok = false;
                options.delayMs = value.toInt(&ok);
                if (!ok || options.delayMs < 0)
                    return Error::usage(
                        QStringLiteral("delay= needs a whole number of ms, not \"%1\"").arg(value));
            } else if (key == QLatin1String("address") && protocol == kRs485Protocol) {
                const Result<int> address = addressFrom(value);
                if (!address) return address.error();
                options.address = *address;
            } else {
                return Error::usage(
                    QStringLiteral("the Compax3 simulator's port takes type=…, serial=…, "
                                   "lacks=…, refuse=…, delay=… and (RS485) address=…, not \"%1\"")
                        .arg(option));
            }
        }
        SimHostOptions shared;
        shared.throttle = false;
        shared.faults.extraDelayMs = options.delayMs;
        return lineFor(options, shared);
    };
    info.options = [] {
        return QList<QCommandLineOption>{
            {QStringLiteral("rs485"),
             QStringLiteral("Compax3: on RS485 (answers only its --address, each with '*'); "
                            "the same as --protocol compax3-rs485.")},
            {QStringLiteral("address"),
             QStringLiteral("Compax3 on RS485: the drive's address 0..99 (default %1).")
                 .arg(kDefaultAddress),
             QStringLiteral("n")},
            {QStringLiteral("drive-type"),
             QStringLiteral("Compax3: the device type its info string names (default %1).")
                 .arg(kDefaultType),
             QStringLiteral("type")},
            {QStringLiteral("serial"),
             QStringLiteral("Compax3: its serial number, object 1.4 (default C3-4711-0815)."),
             QStringLiteral("text")},
            {QStringLiteral("baud"),
             QStringLiteral("Baud rate for the timing (default: the protocol's)."),
             QStringLiteral("rate")},
            {QStringLiteral("lacks"),
             QStringLiteral("Compax3: objects its firmware lacks (answered !0002), e.g. "
                            "1901.0,1902.0."),
             QStringLiteral("objects")},
            {QStringLiteral("refuse"),
             QStringLiteral("Compax3: objects whose reads it answers with !0005 (writes "
                            "still work), e.g. 1000.3."),
             QStringLiteral("objects")},
        };
    };
    info.fromOptions = [](const QCommandLineParser& parser,
                          const SimHostOptions& shared) -> Result<SimulatedLine> {
        DriveOptions options;
        const bool rs485 =
            parser.isSet(QStringLiteral("rs485")) || shared.protocol == kRs485Protocol;
        if (rs485) options.address = kDefaultAddress;
        if (parser.isSet(QStringLiteral("address"))) {
            if (!rs485) return Error::usage(QStringLiteral("--address is for RS485: add --rs485"));
            const Result<int> address = addressFrom(parser.value(QStringLiteral("address")));
            if (!address) return Error::usage(QStringLiteral("--%1").arg(address.error().message));
            options.address = *address;
        }
        if (parser.isSet(QStringLiteral("drive-type")))
            options.type = parser.value(QStringLiteral("drive-type")).trimmed();
        if (parser.isSet(QStringLiteral("serial")))
            options.serial = parser.value(QStringLiteral("serial")).trimmed();
        for (const auto& [name, into] :
             {std::pair{"lacks", &options.lacks}, std::pair{"refuse", &options.refuses}})
            for (const QString& object :
                 parser.value(QLatin1String(name)).split(QLatin1Char(','), Qt::SkipEmptyParts)) {
                const Result<Compax3ObjectId> id = parseCompax3Object(object);
                if (!id)
                    return Error::usage(
                        QStringLiteral("--%1: %2").arg(QLatin1String(name), id.error().message));
                into->append(*id);
            }
        if (parser.isSet(QStringLiteral("baud"))) {
            bool ok = false;
            options.baud = parser.value(QStringLiteral("baud")).toInt(&ok);
            if (!ok || options.baud < 300)
                return Error::usage(QStringLiteral("--baud needs a baud rate of 300 or more."));
        }
        return lineFor(options, shared);
    };
    return info;
}

}  // namespace cambench::comm
