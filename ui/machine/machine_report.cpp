#include "machine_report.h"

#include "machine.h"
#include "machine_progress.h"
#include "machine_report_changes.h"
#include "machine_unit.h"

#include "comm/device/family_registry.h"
#include "ui/device_session.h"
#include "ui/family_gui.h"
#include "ui/report_pages.h"

#include <QDateTime>
#include <QPointer>
#include <QTextDocument>

#include <memory>

namespace cambench {

namespace {

QString escaped(const QString& text) {
    return text.toHtmlEscaped().replace(QLatin1Char('\n'), QStringLiteral("<br>"));
}

QString familyTitle(const QString& familyId) {
    const comm::FamilyInfo* info = comm::FamilyRegistry::instance().find(familyId);
    return info ? QCoreApplication::translate("cambench::comm", info->title.toUtf8().constData())
                : familyId;
}

// The family part of `unit` that speaks for its device.
FamilyGui* deviceFamily(const MachineUnit& unit) {
    for (FamilyGui* family : unit.families())
        if (family->familyId() == unit.device().family) return family;
    return nullptr;
}

QString identityOf(const MachineUnit& unit) {
    const FamilyGui* family = deviceFamily(unit);
    const QString identity = family ? family->identityLine() : QString();
    return identity.isEmpty() ? MachineReport::tr("not identified") : identity;
}

QString when(const QDateTime& time) {
    return time.isValid() ? reportTime(time) : MachineReport::tr("never");
}

QString summary(const Machine& machine) {
    QString html = QStringLiteral("<h1>%1</h1>")
                       .arg(escaped(MachineReport::tr("Machine report: %1").arg(machine.name())));
    html +=
        QStringLiteral("<p>%1</p>")
            .arg(escaped(
                MachineReport::tr("Made %1 by CamBench.").arg(when(QDateTime::currentDateTime()))));
    if (!machine.path().isEmpty())
        html += QStringLiteral("<p>%1</p>")
                    .arg(escaped(MachineReport::tr("Machine file: %1").arg(machine.path())));
    html += QStringLiteral("<table border='1' cellspacing='0' cellpadding='3'><tr>");
    for (const QString& head : {MachineReport::tr("Device"), MachineReport::tr("Family"),
                                MachineReport::tr("Port"), MachineReport::tr("Line"),
                                MachineReport::tr("Identity"), MachineReport::tr("Not written")})
        html += QStringLiteral("<th>%1</th>").arg(escaped(head));
    html += QStringLiteral("</tr>");
    for (const MachineUnit* unit : machine.units()) {
        html += QStringLiteral("<tr>");
        for (const QString& cell :
             {unit->name(), familyTitle(unit->device().family),
              unit->device().option(QStringLiteral("port")), unit->stateText(), identityOf(*unit),
              QString::number(unit->unwrittenCount())})
            html += QStringLiteral("<td>%1</td>").arg(escaped(cell));
        html += QStringLiteral("</tr>");
    }
    return html + QStringLiteral("</table>");
}

QString section(QTextDocument& document, const MachineUnit& unit, int index) {
    QString html = QStringLiteral("<h1 style='page-break-before: always'>%1</h1>")
                       .arg(escaped(MachineReport::tr("%1 (%2)").arg(
                           unit.name(), familyTitle(unit.device().family))));
    const QStringList lines{
        MachineReport::tr("Identity: %1").arg(identityOf(unit)),
        MachineReport::tr("Line: %1 on %2")
            .arg(unit.stateText(), unit.device().option(QStringLiteral("port"))),
        MachineReport::tr("Recorded identity: %1").arg(unit.device().identity.text()),
        // The line's watch asks every device, whichever page is shown.
        MachineReport::tr("Last answered: %1").arg(when(unit.lastAnswer())),
        MachineReport::tr("Edits on this PC not written to the device: %1")
            .arg(unit.unwrittenCount())};
    for (const QString& line : lines) html += QStringLiteral("<p>%1</p>").arg(escaped(line));
    const FamilyGui* family = deviceFamily(unit);
    const QString own =
        family ? family->reportSection(document, QStringLiteral("device%1-").arg(index))
               : QString();
    return html + own;
}

}  // namespace

void MachineReport::read(Machine& machine, MachineProgress* progress, std::function<void()> done) {
    auto left = std::make_shared<int>(int(machine.units().size()));
    const auto oneDone = [left, done] {
        if (--*left == 0 && done) done();
    };
    if (*left == 0 && done) done();
    for (MachineUnit* unit : machine.units()) {
        FamilyGui* family = deviceFamily(*unit);
        // A device that moves is read too: the report's reads are queries.
        const MachineUnit::Lamp lamp = unit->lamp();
        if (!family ||
            (lamp != MachineUnit::Lamp::Connected && lamp != MachineUnit::Lamp::Moving)) {
            progress->finish(
                unit, false,
                tr("not read: %1; its section says what this PC holds.").arg(unit->stateText()));
            oneDone();
            continue;
        }
        QPointer<MachineProgress> shown(progress);
        family->readForReport(progress, [shown, unit, oneDone](const Status& read) {
            if (shown)
                shown->finish(unit, read.ok(),
                              read ? tr("read") : tr("not read: %1").arg(read.error().message));
            oneDone();
        });
    }
}

void MachineReport::build(QTextDocument& document, const Machine& machine,
                          const ReleasedChanges* released) {
    QString html = summary(machine);
    if (released) html += MachineReportChanges::html(*released);
    int index = 0;
    for (const MachineUnit* unit : machine.units()) html += section(document, *unit, index++);
    document.setHtml(html);
}

Status MachineReport::write(const QString& path, const Machine& machine,
                            const ReleasedChanges* released) {
    QTextDocument document;
    build(document, machine, released);
    return writeReportPdf(path, document, tr("Machine report"), tr("Page %1 of %2"));
}

}  // namespace cambench
