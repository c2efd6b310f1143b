#include "mc1_report.h"

#include "comm/mc1/mc1_address.h"
#include "comm/mc1/mc1_variant.h"
#include "comm/mc1/usecases/mc1_backup_restore.h"
#include "ui/device_session.h"
#include "ui/report_pages.h"

namespace cambench {

namespace {

// "V12 = 4711" cells, eight a row: the variables that are not 0.
QString variables(const Mc1Backup& values) {
    constexpr int kPerRow = 8;
    QList<QStringList> rows;
    int zero = 0;
    for (auto it = values.variables.cbegin(); it != values.variables.cend(); ++it) {
        if (it.value() == 0) {
            ++zero;
            continue;
        }
        if (rows.isEmpty() || rows.last().size() == kPerRow) rows.append(QStringList());
        rows.last() << QStringLiteral("V%1 = %2").arg(it.key()).arg(it.value());
    }
    QString html =
        reportParagraph(Mc1Report::tr("%1 variables read (V%2 to V%3); %4 of them are 0 and "
                                      "not listed.")
                            .arg(values.variables.size())
                            .arg(values.variables.isEmpty() ? 0 : values.variables.firstKey())
                            .arg(values.variables.isEmpty() ? 0 : values.variables.lastKey())
                            .arg(zero));
    if (!rows.isEmpty()) html += reportTable({}, rows);
    return html;
}

// The external flags that are set, by their manual names.
QString flags(const Mc1Backup& values) {
    if (values.flags.isEmpty()) return reportParagraph(Mc1Report::tr("The flags were not read."));
    QStringList set;
    const int count = int(values.flags.size()) * 8;
    for (int bit = 0; bit < count; ++bit)
        if (quint8(values.flags.at(bit >> 3)) & (1u << (bit & 7)))
            set << comm::mc1PointText(comm::mc1ExternalFlagAt(bit, values.mc200()));
    if (set.isEmpty())
        return reportParagraph(Mc1Report::tr("All %1 external flags are clear.").arg(count));
    return reportParagraph(
        Mc1Report::tr("Of %1 external flags, these %2 are set: %3. All others are "
                      "clear.")
            .arg(count)
            .arg(set.size())
            .arg(set.join(QStringLiteral(", "))));
}

QString parameterTable(const comm::Mc1AxisParameterTable& parameters) {
    QString html = reportParagraph(
        parameters.provisional
            ? Mc1Report::tr("Parameter table in use: %1 - PROVISIONAL parameter numbers (a guess, "
                            "not from the controller's documentation): the axis values above are "
                            "not facts.")
                  .arg(parameters.source)
            : Mc1Report::tr("Parameter table in use: %1.").arg(parameters.source));
    QList<QStringList> rows;
    for (auto it = parameters.numbers.cbegin(); it != parameters.numbers.cend(); ++it)
        rows << QStringList{QString::number(it.key().first),
                            comm::mc1AxisValueName(it.key().second),
                            QStringLiteral("0x%1").arg(it.value(), 4, 16, QLatin1Char('0'))};
    if (!rows.isEmpty())
        html += reportTable(
            {Mc1Report::tr("Axis"), Mc1Report::tr("Value"), Mc1Report::tr("Parameter")}, rows);
    return html;
}

}  // namespace

void Mc1Report::read(DeviceSession* session, QObject* context,
                     std::function<void(Result<Mc1ReportReading>)> done) {
    session->run<comm::Mc1Device, Mc1ReportReading>(
        context, tr("Read the controller for the report"),
        [](comm::Mc1Device& device, comm::JobContext& job) -> Result<Mc1ReportReading> {
            const Result<comm::Mc1Variant> variant = device.ensureIdentified();
            if (!variant) return variant.error();
            Mc1ReportReading reading;
            reading.controller = QStringLiteral("%1 (%2)").arg(comm::mc1VariantName(*variant),
                                                               device.variantSource());
            // Variables and flags as a backup takes them (with the identity).
            const Result<Mc1Backup> values =
                usecases::takeMc1Backup(device, usecases::defaultMc1BackupScope(*variant),
                                        usecases::UseCaseProgress::of(job));
            if (!values && values.error().kind == ErrorKind::Cancelled) return values.error();
            if (values)
                reading.values = *values;
            else
                reading.valuesNote = values.error().message;
            if (device.has(comm::Mc1Capability::ProgramControl)) {
                const Result<comm::Mc1ProgramStatus> program = device.programStatus();
                if (program)
                    reading.program = *program;
                else
                    reading.programNote = program.error().message;
            } else {
                reading.programNote =
                    tr("the %1 reports no program state").arg(comm::mc1VariantName(*variant));
            }
            reading.parameters = device.axisParameters();
            if (device.has(comm::Mc1Capability::Axes)) {
                const Result<comm::Mc1Axes> axes = device.axes();
                if (!axes) {
                    reading.axesNote = axes.error().message;
                } else {
                    reading.axesNote = axes->source;
                    for (int axis : axes->numbers) {
                        const Result<comm::Mc1AxisState> state = device.axisState(axis);
                        if (!state) {
                            reading.axesNote =
                                tr("axis %1: %2").arg(axis).arg(state.error().message);
                            break;
                        }
                        reading.axes << *state;
                    }
                }
            } else {
                reading.axesNote =
                    tr("the %1 has no axis telegrams").arg(comm::mc1VariantName(*variant));
            }
            reading.read = QDateTime::currentDateTime();
            return reading;
        },
        std::move(done));
}

QString Mc1Report::html(const std::optional<Mc1ReportReading>& reading) {
    if (!reading || !reading->read.isValid())
        return reportParagraph(tr("Not read from the controller for this report."));
    const Mc1ReportReading& r = *reading;
    QString html = reportParagraph(tr("Read from the controller at %1.").arg(reportTime(r.read)));
    html += reportHeading(tr("Controller"));
    html += reportParagraph(r.controller);
    if (r.values && r.values->identity.known())
        html += reportParagraph(tr("Identity: %1").arg(r.values->identity.text()));
    html += reportHeading(tr("PLC program"));
    html +=
        reportParagraph(r.program ? r.program->summary() : tr("Not read: %1").arg(r.programNote));
    if (r.program && !r.program->flagTexts().isEmpty())
        html += reportParagraph(r.program->flagTexts().join(QStringLiteral(", ")));
    html += reportHeading(tr("Axes"));
    if (r.axes.isEmpty()) {
        html += reportParagraph(tr("No axis read: %1").arg(r.axesNote));
    } else {
        QList<QStringList> rows;
        for (const comm::Mc1AxisState& axis : r.axes)
            rows << QStringList{QString::number(axis.axis), QString::number(axis.position),
                                QString::number(axis.target),
                                axis.error    ? tr("error")
                                : axis.moving ? tr("moving")
                                              : tr("standing"),
                                axis.homed ? tr("yes") : tr("no")};
        html +=
            reportTable({tr("Axis"), tr("Position"), tr("Target"), tr("State"), tr("Homed")}, rows);
        html += reportParagraph(tr("Axes: %1.").arg(r.axesNote));
    }
    html += parameterTable(r.parameters);
    html += reportHeading(tr("Variables"));
    html += r.values ? variables(*r.values) : reportParagraph(tr("Not read: %1").arg(r.valuesNote));
    html += reportHeading(tr("External flags"));
    html += r.values ? flags(*r.values) : reportParagraph(tr("Not read: %1").arg(r.valuesNote));
    return html;
}

}  // namespace cambench
