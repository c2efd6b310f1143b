#include "compax3_report.h"

#include "comm/compax3/compax3_objects.h"
#include "ui/device_session.h"
#include "ui/language.h"
#include "ui/report_pages.h"

namespace cambench {

namespace {

QString status(const comm::Compax3DriveStatus& drive) {
    QString html = reportParagraph(drive.summary());
    html += reportParagraph(Compax3Report::tr("Last error (550.1): %1")
                                .arg(comm::compax3LastErrorText(drive.lastError)));
    QStringList on;
    for (const comm::Compax3StatusBit& bit : comm::compax3StatusBits(drive.status.word))
        if (bit.on) on << bit.name;
    html += reportParagraph(
        Compax3Report::tr("Status word (1000.3): %1; set: %2")
            .arg(compax3HexText(drive.status.word, 4),
                 on.isEmpty() ? Compax3Report::tr("none") : on.join(QStringLiteral(", "))));
    return html;
}

// One row per object: number, name, value, unit.
QString parameters(const usecases::Compax3Backup& backup, const Compax3Dictionary& dictionary) {
    const QString language = currentLanguage();
    QList<QStringList> rows;
    for (const Compax3ParameterValue& value : backup.set.values) {
        const Compax3ObjectInfo* info = dictionary.find(value.id);
        rows << QStringList{value.id.text(), info ? info->nameIn(language) : QString(), value.value,
                            info ? info->unit : QString()};
    }
    QString html = reportTable({Compax3Report::tr("Object"), Compax3Report::tr("Name"),
                                Compax3Report::tr("Value"), Compax3Report::tr("Unit")},
                               rows);
    QStringList absent;
    for (const Compax3ObjectId& id : backup.set.absent) absent << id.text();
    if (!absent.isEmpty())
        html += reportParagraph(
            Compax3Report::tr("Not on this drive: %1.").arg(absent.join(QStringLiteral(", "))));
    for (const usecases::Compax3Refusal& refusal : backup.refused)
        html += reportParagraph(
            Compax3Report::tr("%1 not read: %2").arg(refusal.id.text(), refusal.reason));
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
        return reportParagraph(tr("Not read from the drive for this report."));
    const Compax3ReportReading& r = *reading;
    QString html = reportParagraph(tr("Read from the drive at %1.").arg(reportTime(r.read)));
    html += reportHeading(tr("Drive"));
    if (r.parameters) {
        const Compax3Identity& drive = r.parameters->set.drive;
        html += reportParagraph(drive.info);
        html += reportParagraph(tr("Serial number %1, type %2").arg(drive.serial, drive.type()));
    }
    html += reportHeading(tr("Status"));
    html += r.status ? status(*r.status) : reportParagraph(tr("Not read: %1").arg(r.statusNote));
    html += reportHeading(tr("Parameter set"));
    html += r.parameters ? parameters(*r.parameters, dictionary)
                         : reportParagraph(tr("Not read: %1").arg(r.parametersNote));
    return html;
}

}  // namespace cambench
