#include "mc1_simulator.h"

#include "sim_mc1_line.h"

#include "comm/mc1/mc1_address.h"

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

}  // namespace

SimulatedLine mc1SimulatedLine(Mc1Variant variant, int baud, const SimHostOptions& shared) {
    auto line = std::make_unique<SimMc1Line>(variant, shared.faults);
    addDemoState(line->controller());
    const QString description =
        QStringLiteral("simulator (%1, %2 baud%3)")
            .arg(mc1VariantName(variant))
            .arg(baud)
            .arg(shared.throttle ? QString() : QStringLiteral(", unthrottled"));
    return {std::move(line), SimPacer(baud, shared.throttle, 10), description};
}

void registerMc1Simulator(SimulatorRegistry& registry) {
    SimulatorInfo info;
    info.familyId = QStringLiteral("mc1");
    // "sim" or "sim:variant=mc100v1": the in-process simulator.
    info.fromPort = [](const QString& port, const SerialSettings& serial,
                       const QString&) -> Result<SimulatedLine> {
        Mc1Variant variant = kDefaultVariant;
        const QString options = port.section(QLatin1Char(':'), 1);
        for (const QString& option : options.split(QLatin1Char(';'), Qt::SkipEmptyParts)) {
            const QString key = option.section(QLatin1Char('='), 0, 0).trimmed();
            const QString value = option.section(QLatin1Char('='), 1);
            if (key != QLatin1String("variant"))
                return Error::usage(
                    QStringLiteral("the MC-1 simulator's port takes variant=…, not \"%1\"")
                        .arg(option));
            const Result<Mc1Variant> parsed = variantFrom(value);
            if (!parsed) return parsed.error();
            variant = *parsed;
        }
        SimHostOptions shared;
        shared.throttle = false;
        return mc1SimulatedLine(variant, serial.baud, shared);
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
        };
    };
    info.fromOptions = [](const QCommandLineParser& parser,
                          const SimHostOptions& shared) -> Result<SimulatedLine> {
        Mc1Variant variant = kDefaultVariant;
        if (parser.isSet(QStringLiteral("variant"))) {
            const Result<Mc1Variant> parsed = variantFrom(parser.value(QStringLiteral("variant")));
            if (!parsed) return Error::usage(QStringLiteral("--%1").arg(parsed.error().message));
            variant = *parsed;
        }
        int baud = kDefaultBaud;
        if (parser.isSet(QStringLiteral("baud"))) {
            bool ok = false;
            baud = parser.value(QStringLiteral("baud")).toInt(&ok);
            if (!ok || baud < 300)
                return Error::usage(QStringLiteral("--baud needs a baud rate of 300 or more."));
        }
        return mc1SimulatedLine(variant, baud, shared);
    };
    registry.add(info);
}

}  // namespace cambench::comm
