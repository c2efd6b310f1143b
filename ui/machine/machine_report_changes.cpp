#include "machine_report_changes.h"

#include "machine_history_jobs.h"

#include "model/machine/machine_archive.h"
#include "ui/report_pages.h"

#include <memory>

namespace cambench {

namespace {

using Kind = usecases::DeviceChange::Kind;

QString escaped(const QString& text) {
    return text.toHtmlEscaped().replace(QLatin1Char('\n'), QStringLiteral("<br>"));
}

// The released version in words; `id` when it is not among the versions.
QString versionText(const MachineArchive& archive, const QString& id) {
    const Result<QList<ArchiveVersion>> versions = archive.versions();
    if (versions)
        for (const ArchiveVersion& version : *versions) {
            if (version.id != id) continue;
            QString text = MachineReportChanges::tr("%1: version %2 of %3 by %4")
                               .arg(version.releases.value(0), version.shortId(),
                                    reportTime(version.time), version.author);
            if (!version.note.isEmpty()) text += QStringLiteral(" (%1)").arg(version.note);
            return text;
        }
    return MachineReportChanges::tr("version %1").arg(id.left(10));
}

}  // namespace

QString MachineReportChanges::deviceLine(const usecases::DeviceChange& change) {
    switch (change.kind) {
        case Kind::Equal:
            return change.volatileLeftOut == 0
                       ? tr("equal to the released version")
                       : tr("equal to the released version (%n change(s) of volatile items "
                            "left out)",
                            nullptr, change.volatileLeftOut);
        case Kind::Changed:
            return tr("DIFFERS: %n difference(s)", nullptr,
                      int(change.differences.size()) + (change.identity.isEmpty() ? 0 : 1));
        case Kind::Added:
            return tr("not in the released version: not compared");
        case Kind::Removed:
            return tr("in the released version, but no longer a device of this machine");
        case Kind::NotSaved:
        case Kind::NotCompared:
            return tr("NOT COMPARED: %1").arg(change.why);
    }
    return {};
}

void MachineReportChanges::compare(Machine* machine, const QString& archive, QObject* context,
                                   std::function<void(ReleasedChanges)> done) {
    ReleasedChanges said;
    said.archive = archive;
    const Result<MachineArchive> opened = MachineArchive::open(archive);
    if (!opened) {
        said.problem = opened.error().message;
        done(said);
        return;
    }
    const Result<QString> released = opened->released();
    if (!released) {
        said.problem = released.error().message;
        done(said);
        return;
    }
    said.version = versionText(*opened, *released);
    Result<usecases::VersionFolder> taken = usecases::takeOutVersion(*opened, *released);
    if (!taken) {
        said.problem = taken.error().message;
        done(said);
        return;
    }
    // The folder stays while the devices' jobs read it.
    auto folder = std::make_shared<usecases::VersionFolder>(std::move(taken).value());
    auto* jobs = new MachineHistoryJobs(machine, context);
    jobs->compareWithDevices(
        folder->path(), [folder, jobs, said, done](const usecases::MachineChanges& changes,
                                                   const usecases::MachineFolderRead&) mutable {
            said.changes = changes;
            jobs->deleteLater();
            done(said);
        });
}

QString MachineReportChanges::html(const ReleasedChanges& changes) {
    QString html =
        QStringLiteral("<h2>%1</h2>").arg(escaped(tr("Changes since the released version")));
    const auto paragraph = [&html](const QString& text) {
        html += QStringLiteral("<p>%1</p>").arg(escaped(text));
    };
    if (changes.archive.isEmpty()) {
        paragraph(tr("Not part of this report: no machine archive was chosen."));
        return html;
    }
    paragraph(tr("Archive: %1").arg(changes.archive));
    if (!changes.problem.isEmpty()) {
        paragraph(tr("Nothing was compared: %1").arg(changes.problem));
        return html;
    }
    paragraph(tr("Released version: %1").arg(changes.version));
    paragraph(
        tr("Each device was read for this report and compared with its backup in that "
           "version."));
    html += QStringLiteral(
                "<table border='1' cellspacing='0' cellpadding='3'><tr><th>%1</th>"
                "<th>%2</th></tr>")
                .arg(escaped(tr("Device")), escaped(tr("Since the released version")));
    for (const usecases::DeviceChange& change : changes.changes.devices) {
        QString cell = escaped(deviceLine(change));
        QStringList lines;
        if (!change.identity.isEmpty()) lines << change.identity;
        for (const BackupDifference& difference : change.differences) lines << difference.text;
        if (!lines.isEmpty()) cell += QStringLiteral("<br>") + escaped(lines.join(u'\n'));
        html += QStringLiteral("<tr><td>%1</td><td>%2</td></tr>").arg(escaped(change.name), cell);
    }
    return html + QStringLiteral("</table>");
}

}  // namespace cambench
