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

// The axes RDTABLE finds (their values are the parameter table's check).
CheckResult axes(Mc1Device& device) {
    const Reading reading{
        QStringLiteral("mc1.axes"),
        QCoreApplication::translate("cambench::usecases",
                                    "RDTABLE answers for each logical axis 1..8 the controller "
                                    "has (logical n is physical n-1)"),
        QStringLiteral("comm/mc1/mc1_parameters.h (kMc1FirstAxis..)")};
    if (!device.has(comm::Mc1Capability::Axes))
        return reading.couldNotTell(QCoreApplication::translate(
            "cambench::usecases", "this variant has no axis telegrams"));
    const Result<comm::Mc1Axes> present = device.axes();
    if (!present) return reading.failed(present.error());
    QStringList numbers;
    for (const int axis : present->numbers) numbers << QString::number(axis);
    if (numbers.isEmpty()) return reading.refuted(present->source);
    return reading.held(QCoreApplication::translate("cambench::usecases", "axes %1 (%2)")
                            .arg(numbers.join(QLatin1String(", ")), present->source));
}

// Where the table in use comes from, for the report: the built-in guess
// (marked provisional) or the file it was loaded from.
QString tableSource(const comm::Mc1AxisParameterTable& table) {
    return table.provisional ? QStringLiteral(
                                   "provisional: built-in guess, comm/mc1/mc1_parameters.cpp "
                                   "(comm/mc1/README.md)")
                             : table.source;
}

// Each parameter of the table in use read on each axis the controller
// has, one verdict each: answered is held, refused is refuted (naming the
// number). A line failure decides nothing and ends the table's check.
QList<CheckResult> axisParameterTable(Mc1Device& device) {
    const comm::Mc1AxisParameterTable& table = device.axisParameters();
    const QString source = tableSource(table);
    const Reading whole{
        QStringLiteral("mc1.axis_parameter_table"),
        QCoreApplication::translate("cambench::usecases", "the axis parameter table in use (%1)")
            .arg(table.source),
        source};
    if (!device.has(comm::Mc1Capability::Axes))
        return {whole.couldNotTell(QCoreApplication::translate(
            "cambench::usecases", "this variant has no axis telegrams"))};
    const Result<comm::Mc1Axes> present = device.axes();
    if (!present) return {whole.failed(present.error())};
    if (present->numbers.isEmpty())
        return {whole.couldNotTell(
            QCoreApplication::translate("cambench::usecases", "the controller has no axes (%1)")
                .arg(present->source))};
    QList<CheckResult> results;
    for (const int axis : present->numbers) {
        for (const comm::Mc1AxisValue value :
             {comm::Mc1AxisValue::Position, comm::Mc1AxisValue::Target,
              comm::Mc1AxisValue::Status}) {
            const QString name = comm::mc1AxisValueName(value);
            const std::optional<quint16> number = table.number(axis, value);
            const Reading reading{
                QStringLiteral("mc1.axis_parameter.%1.%2").arg(axis).arg(name),
                number ? QCoreApplication::translate("cambench::usecases",
                                                     "the %1 of axis %2 is RDSTAT parameter %3 "
                                                     "(0x%4)")
                             .arg(name)
                             .arg(axis)
                             .arg(*number)
                             .arg(*number, 4, 16, QLatin1Char('0'))
                       : QCoreApplication::translate("cambench::usecases",
                                                     "the %1 of axis %2 (the table names no "
                                                     "parameter for it)")
                             .arg(name)
                             .arg(axis),
                source};
            if (!number) {
                results << reading.couldNotTell(QCoreApplication::translate(
                    "cambench::usecases", "not in the table, not read"));
                continue;
            }
            const Result<qint32> answered = device.axisValue(axis, value);
            const CheckResult result =
                answered
                    ? reading.held(QCoreApplication::translate("cambench::usecases", "answered %1")
                                       .arg(*answered))
                    : reading.failed(answered.error());
            results << result;
            if (result.verdict == CheckVerdict::CouldNotTell) return results;
        }
    }
    return results;
}

Result<QList<CheckResult>> run(comm::DeviceConnection& connection,
                               const UseCaseProgress& progress) {
    auto* device = dynamic_cast<Mc1Device*>(&connection);
    if (!device) return Error::usage(QStringLiteral("not an MC-1 connection"));
    const QList<CheckResult (*)(Mc1Device&)> checks{variantProbe, variableWidth, flagAddressing,
                                                    ioAddressing, axes};
    QList<CheckResult> results;
    for (const auto check : checks) {
        if (progress.cancelled()) return Error::cancelled();
        progress.report(results.size(), checks.size() + 1);
        results << check(*device);
    }
    if (progress.cancelled()) return Error::cancelled();
    progress.report(checks.size(), checks.size() + 1);
    results << axisParameterTable(*device);
    return results;
}

// --parameters FILE: the controller's own axis parameter table.
Result<CheckTable> parametersFile(const QString& path) {
    const Result<comm::Mc1AxisParameterTable> table = comm::loadMc1AxisParameterTable(path);
    if (!table) return table.error();
    return CheckTable{{}, {}, [table = *table](comm::DeviceConnection& connection) {
                          if (auto* device = dynamic_cast<Mc1Device*>(&connection))
                              device->setAxisParameters(table);
                      }};
}

}  // namespace

FamilyCheck mc1Check() {
    FamilyCheck check;
    check.refuses = refuses;
    check.run = run;
    check.tables = {CheckTableOption{QStringLiteral("--parameters"), parametersFile}};
    return check;
}

}  // namespace cambench::usecases
