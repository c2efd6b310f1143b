#include "compax3_report.h"

#include "comm/compax3/compax3_objects.h"
#include "ui/device_session.h"
#include "ui/language.h"
#include "ui/report_pages.h"

namespace cambench {

namespace {

QString paragraph(const QString& text) {
    return QStringLiteral("<p>%1</p>").arg(text.toHtmlEscaped());
}

QString heading(const QString& text) {
    return QStringLiteral("<h2>%1</h2>").arg(text.toHtmlEscaped());
}

QString row(const QStringList& cells, const char* tag) {
    QString html = QStringLiteral("<tr>");
    for (const QString& cell : cells)
        html += QStringLiteral("<%1>%2</%1>").arg(QLatin1String(tag), cell.toHtmlEscaped());
    return html + QStringLiteral("</tr>");
}

QString status(const comm::Compax3DriveStatus& drive) {
    QString html = paragraph(drive.summary());
    html += paragraph(Compax3Report::tr("Last error (550.1): %1")
                          .arg(comm::compax3LastErrorText(drive.lastError)));
    QStringList on;
    for (const comm::Compax3StatusBit& bit : comm::compax3StatusBits(drive.status.word))
        if (bit.on) on << bit.name;
    html += paragraph(
        Compax3Report::tr("Status word (1000.3): %1; set: %2")
            .arg(compax3HexText(drive.status.word, 4),
                 on.isEmpty() ? Compax3Report::tr("none") : on.join(QStringLiteral(", "))));
    return html;
}

// One row per object: number, name, value, unit.
QString parameters(const usecases::Compax3Backup& backup, const Compax3Dictionary& dictionary) {
    const QString language = currentLanguage();
    QString html = QStringLiteral("<table border='1' cellspacing='0' cellpadding='3'>");
    html += row({Compax3Report::tr("Object"), Compax3Report::tr("Name"), Compax3Report::tr("Value"),
                 Compax3Report::tr("Unit")},
                "th");
    for (const Compax3ParameterValue& value : backup.set.values) {
        const Compax3ObjectInfo* info = dictionary.find(value.id);
        html += row({value.id.text(), info ? info->nameIn(language) : QString(), value.value,
                     info ? info->unit : QString()},
                    "td");
    }
    html += QStringLiteral("</table>");
    QStringList absent;
    for (const Compax3ObjectId& id : backup.set.absent) absent << id.text();
    if (!absent.isEmpty())
        html += paragraph(
            Compax3Report::tr("Not on this drive: %1.").arg(absent.join(QStringLiteral(", "))));
    for (const usecases::Compax3Refusal& refusal : backup.refused)
        html +=
            paragraph(Compax3Report::tr("%1 not read: %2").arg(refusal.id.text(), refusal.reason));
    return html;
}

}  // namespace

void Compax3Report::read(DeviceSession* session, QObject* context,
                         const Compax3Dictionary& dictionary,
                         std::function<void(Result<Compax3ReportReading>)> done) {
    session->run<comm::Compax3Device, Compax3ReportReading>(
        context, tr("Read the drive for the report"),
        [dictionary](comm::Compax3Device& device,
                     comm::JobContext& job) -> Result<Compax3ReportReading> {
            Compax3ReportReading reading;
            const Result<comm::Compax3DriveStatus> drive = device.status();
            if (!drive && drive.error().kind == ErrorKind::Cancelled) return drive.error();
            if (drive)
                reading.status = *drive;
            else
                reading.statusNote = drive.error().message;
            // The parameter set as a backup takes it, with the identity.
            const Result<usecases::Compax3Backup> set = usecases::takeCompax3Parameters(
                device, dictionary.parameters(), dictionary, usecases::UseCaseProgress::of(job));
            if (!set && set.error().kind == ErrorKind::Cancelled) return set.error();
            if (set)
                reading.parameters = *set;
            else
                reading.parametersNote = set.error().message;
            reading.read = QDateTime::currentDateTime();
            return reading;
        },
        std::move(done));
}

QString Compax3Report::html(const std::optional<Compax3ReportReading>& reading,
                            const Compax3Dictionary& dictionary) {
    if (!reading || !reading->read.isValid())
        return paragraph(tr("Not read from the drive for this report."));
    const Compax3ReportReading& r = *reading;
    QString html = paragraph(tr("Read from the drive at %1.").arg(reportTime(r.read)));
    html += heading(tr("Drive"));
    if (r.parameters) {
        const Compax3Identity& drive = r.parameters->set.drive;
        html += paragraph(drive.info);
        html += paragraph(tr("Serial number %1, type %2").arg(drive.serial, drive.type()));
    }
    html += heading(tr("Status"));
    html += r.status ? status(*r.status) : paragraph(tr("Not read: %1").arg(r.statusNote));
    html += heading(tr("Parameter set"));
    html += r.parameters ? parameters(*r.parameters, dictionary)
                         : paragraph(tr("Not read: %1").arg(r.parametersNote));
    return html;
}

}  // namespace cambench
