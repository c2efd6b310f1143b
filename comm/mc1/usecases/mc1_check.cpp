#include "mc1_check.h"

#include "comm/mc1/mc1_ascii.h"
#include "comm/mc1/mc1_catalogue.h"
#include "comm/mc1/mc1_device.h"
#include "comm/mc1/mc1_parameters.h"

#include <QCoreApplication>

namespace cambench::usecases {

namespace {

using comm::Mc1Device;

// Flags compared between their own reads and their RAM page.
constexpr int kComparedFlags = 16;
// Inputs and outputs read from 1 on.
constexpr int kReadPoints = 8;

// A telegram that reads on every variant that knows it, or an ASCII query
// ("V1=?", "M5=?"); anything else is refused.
QString refuses(const QString& protocolId, const comm::Request& request) {
    bool reads = false;
    if (protocolId == QLatin1String("mc1-ascii")) {
        // Without its CR.
        const std::optional<comm::Mc1AsciiRequest> parsed =
            comm::parseMc1AsciiRequest(request.message.trimmed());
        reads = parsed && !parsed->value;
    } else {
        bool known = false;
        reads = true;
        for (const comm::Mc1Variant variant : comm::allMc1Variants()) {
            const comm::Mc1Telegram* row = comm::mc1RequestRow(variant, request.message);
            if (!row) continue;
            known = true;
            reads = reads && row->retry == comm::Mc1Retry::Read;
        }
        reads = reads && known;
    }
    return reads ? QString() : notReadingRequest(request);
}

CheckResult variantProbe(Mc1Device& device) {
    const Reading reading{QStringLiteral("mc1.variant_probe"),
                          QCoreApplication::translate("cambench::usecases",
                                                      "the variant shows in RDVAR's width, then in "
                                                      "SYSDATA or RDBLOCK being answered"),
                          QStringLiteral("comm/mc1/mc1_controller.cpp (ensureIdentified)")};
    const Result<comm::Mc1Variant> variant = device.ensureIdentified();
    if (!variant) return reading.failed(variant.error());
    return reading.held(
        QStringLiteral("%1 (%2)").arg(comm::mc1VariantName(*variant), device.variantSource()));
}

CheckResult variableWidth(Mc1Device& device) {
    const Reading reading{
        QStringLiteral("mc1.variable_width"),
        QCoreApplication::translate("cambench::usecases",
                                    "RDVAR answers 24 bits on an MC100 and 32 bits on an "
                                    "MC200, two's complement (P3)"),
        QStringLiteral("comm/mc1/mc1_catalogue.cpp (RDVAR, kP3)")};
    const Result<qint64> first = device.readVariable(1);
    return first ? reading.held() : reading.failed(first.error());
}

// The flags of the external page read one by one and as the page's bytes
// must agree (tables 47/48: which bit of which page is which flag).
CheckResult flagAddressing(Mc1Device& device) {
    const Reading reading{
        QStringLiteral("mc1.flag_addressing"),
        QCoreApplication::translate("cambench::usecases",
                                    "flag Mn read by itself and bit n-1 of the flags' "
                                    "external RAM page agree"),
        QStringLiteral("comm/mc1/mc1_address.cpp (mc1ExternalFlagAt)")};
    const bool mc200 = comm::isMc200(device.variant());
    QList<comm::Mc1Point> points;
    for (int i = 0; i < kComparedFlags; ++i) points << comm::mc1ExternalFlagAt(i, mc200);
    const Result<QList<bool>> single = device.readPoints(points);
    if (!single) return reading.failed(single.error());
    // The ASCII protocol has no page read: nothing to compare with.
    const Result<QByteArray> page = device.readExternalPage(comm::mc1ExternalFlagPage(mc200));
    if (!page) return reading.couldNotTell(page.error().message);
    QStringList differ;
    for (int i = 0; i < kComparedFlags && i / 8 < page->size(); ++i) {
        const bool inPage = (quint8(page->at(i / 8)) >> (i % 8)) & 1;
        if (inPage != single->at(i)) differ << comm::mc1PointText(points.at(i));
    }
    if (differ.isEmpty()) return reading.held();
    return reading.refuted(QCoreApplication::translate("cambench::usecases",
                                                       "read by themselves, %1 differ from the "
                                                       "page (or changed between the reads)")
                               .arg(differ.join(QLatin1String(", "))));
}

CheckResult ioAddressing(Mc1Device& device) {
    const Reading reading{
        QStringLiteral("mc1.io_addressing"),
        QCoreApplication::translate("cambench::usecases",
                                    "inputs E1..E8 and outputs A1..A8 are read at the "
                                    "addresses of tables 47/48 and answered"),
        QStringLiteral("comm/mc1/mc1_address.cpp (mc1BitAddress)")};
    QList<comm::Mc1Point> points;
    for (int n = 1; n <= kReadPoints; ++n) {
        points << comm::Mc1Point{comm::Mc1Area::Input, n}
               << comm::Mc1Point{comm::Mc1Area::Output, n};
    }
    const Result<QList<bool>> read = device.readPoints(points);
    return read ? reading.held() : reading.failed(read.error());
}

CheckResult axes(Mc1Device& device) {
    const Reading reading{
        QStringLiteral("mc1.axes"),
        QCoreApplication::translate("cambench::usecases",
                                    "axes 1..8 answer their state (RDSTAT 0x1000 + 0x10 x "
                                    "axis; logical n is physical n-1)"),
        QStringLiteral("comm/mc1/mc1_parameters.h (kMc1FirstAxis..)")};
    if (!device.has(comm::Mc1Capability::Axes))
        return reading.couldNotTell(QCoreApplication::translate(
            "cambench::usecases", "this variant has no axis telegrams"));
    // A controller with fewer axes may refuse the others: the first
    // refusal ends the list, a line failure decides nothing.
    QStringList answered;
    QString refusal;
    for (int axis = comm::kMc1FirstAxis; axis <= comm::kMc1LastAxis && refusal.isEmpty(); ++axis) {
        const Result<comm::Mc1AxisState> state = device.axisState(axis);
        if (state) {
            answered << QString::number(axis);
        } else if (reading.failed(state.error()).verdict == CheckVerdict::Refuted) {
            refusal = state.error().message;
        } else {
            return reading.failed(state.error());
        }
    }
    if (answered.isEmpty()) return reading.refuted(refusal);
    QString observed = QCoreApplication::translate("cambench::usecases", "axes %1 answered")
                           .arg(answered.join(QLatin1String(", ")));
    if (!refusal.isEmpty()) observed += QStringLiteral("; ") + refusal;
    return reading.held(observed);
}

// TODO(lead): the axis parameter table read from a file (the MC-1
// branch's work) gets its check here once both are merged.
CheckResult axisParameterTable(Mc1Device&) {
    const Reading reading{
        QStringLiteral("mc1.axis_parameter_table"),
        QCoreApplication::translate("cambench::usecases",
                                    "the axis parameter table (the MC-1B manual's numbers)"),
        QStringLiteral("comm/mc1/mc1_parameters.h")};
    return reading.couldNotTell(QCoreApplication::translate("cambench::usecases", "not built yet"));
}

Result<QList<CheckResult>> run(comm::DeviceConnection& connection,
                               const UseCaseProgress& progress) {
    auto* device = dynamic_cast<Mc1Device*>(&connection);
    if (!device) return Error::usage(QStringLiteral("not an MC-1 connection"));
    const QList<CheckResult (*)(Mc1Device&)> checks{
        variantProbe, variableWidth, flagAddressing, ioAddressing, axes, axisParameterTable};
    QList<CheckResult> results;
    for (const auto check : checks) {
        if (progress.cancelled()) return Error::cancelled();
        progress.report(results.size(), checks.size());
        results << check(*device);
    }
    return results;
}

}  // namespace

void registerMc1Check(CheckRegistry& registry) {
    registry.add({QStringLiteral("mc1"), refuses, run});
}

}  // namespace cambench::usecases
