#include "commissioning_report.h"

#include "setting_field.h"
#include "workspace.h"

#include "ui/cameditor/cam_diagram_widget.h"
#include "ui/cameditor/cam_document.h"

#include <QApplication>
#include <QCoreApplication>
#include <QDateTime>
#include <QFile>
#include <QImage>
#include <QLocale>
#include <QPageSize>
#include <QPdfWriter>
#include <QSaveFile>
#include <QStyle>
#include <QTextDocument>
#include <QUrl>

namespace cambench {

namespace {

QString row(const QString& label, const QString& value) {
    return QStringLiteral("<tr><td>%1</td><td>%2</td></tr>").arg(label.toHtmlEscaped(), value.toHtmlEscaped());
}

QString table(const QString& rows) {
    return QStringLiteral("<table border='1' cellspacing='0' cellpadding='3'>%1</table>").arg(rows);
}

// The diagram as printed: always the light palette, whatever the screen uses.
QImage diagramImage(CamDocument* cams, int program) {
    CamDiagramWidget diagram(cams);
    diagram.setPalette(QApplication::style()->standardPalette());
    diagram.setProgram(program);
    diagram.resize(1100, std::min(1400, std::max(200, diagram.sizeHint().height())));
    diagram.zoomFit();
    return diagram.grab().toImage();
}

}  // namespace

void CommissioningReport::build(QTextDocument& document, const Workspace& workspace) {
    const DeviceInfo& info = workspace.info();
    CamDocument* cams = workspace.cams();
    const QLocale locale;
    QString html = QStringLiteral("<h1>%1</h1><p>%2</p>")
                       .arg(tr("Commissioning report"),
                            tr("Created %1 with CamBench %2")
                                .arg(locale.toString(QDateTime::currentDateTime(), QLocale::LongFormat),
                                     QStringLiteral(CAMBENCH_VERSION))
                                .toHtmlEscaped());

    html += QStringLiteral("<h2>%1</h2>").arg(tr("Device"));
    QString rows;
    if (workspace.infoFromDevice()) {
        rows += row(tr("Firmware (EPROM date)"), info.epromDate);
        rows += row(tr("Device number"), QString::number(info.deviceNumber));
    } else {
        rows += row(tr("Source"), tr("offline project, not read from a device"));
    }
    rows += row(tr("Outputs / inputs"), QStringLiteral("%1 / %2").arg(info.outputs).arg(info.inputs));
    rows += row(tr("Programs"), QString::number(info.programs));
    rows += row(tr("Position range"), QStringLiteral("%1 … %2").arg(info.minPosition).arg(info.maxPosition));
    html += table(rows);

    html += QStringLiteral("<h2>%1</h2>").arg(tr("Settings"));
    rows.clear();
    for (const SettingSpec& spec : settingSpecs()) {
        const QString key = QString::fromLatin1(spec.key);
        if (!workspace.settings().contains(key)) continue;
        QString value = SettingField::displayText(spec, workspace.settings().value(key));
        if (*spec.unit) value += QLatin1Char(' ') + QCoreApplication::translate("Settings", spec.unit);
        rows += row(SettingField::labelText(spec), value);
    }
    html += rows.isEmpty() ? QStringLiteral("<p>%1</p>").arg(tr("Settings not read.")) : table(rows);

    html += QStringLiteral("<h2>%1</h2>").arg(tr("Outputs and dead times"));
    rows = QStringLiteral("<tr><th>%1</th><th>%2</th><th>%3</th></tr>").arg(tr("Output"), tr("Name"), tr("Dead time"));
    for (int output = 1; output <= info.outputs; ++output) {
        rows += QStringLiteral("<tr><td>%1</td><td>%2</td><td>%3 ms</td></tr>")
                    .arg(output)
                    .arg(cams->outputName(output).toHtmlEscaped())
                    .arg(locale.toString(cams->deadTime(output) / 10.0, 'f', 1));
    }
    html += table(rows);

    for (int number : cams->editedPrograms()) {
        const CamProgram program = cams->program(number);
        if (program.tracks.isEmpty()) continue;
        html += QStringLiteral("<h2>%1</h2>")
                    .arg(program.name.isEmpty() ? tr("Program %1").arg(number)
                                                : tr("Program %1: %2").arg(number).arg(program.name).toHtmlEscaped());
        const QString resource = QStringLiteral("diagram%1.png").arg(number);
        const QImage image = diagramImage(cams, number);
        document.addResource(QTextDocument::ImageResource, QUrl(resource), image);
        html += QStringLiteral("<p><img src='%1' width='640'></p>").arg(resource);
        rows = QStringLiteral("<tr><th>%1</th><th>%2</th><th>%3</th></tr>").arg(tr("Output"), tr("Switch on"), tr("Switch off"));
        for (const Track& track : program.tracks) {
            for (const Cam& cam : track.cams)
                rows += QStringLiteral("<tr><td>%1</td><td>%2</td><td>%3</td></tr>").arg(track.output).arg(cam.on).arg(cam.off);
        }
        html += table(rows);
    }
    document.setHtml(html);
}

Status CommissioningReport::write(const QString& path, const Workspace& workspace) {
    QTextDocument document;
    build(document, workspace);
    // QPdfWriter writes straight into its target: render into a QSaveFile.
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return Error::invalidData(tr("Cannot write the report to %1: %2").arg(path, file.errorString()));
    {
        QPdfWriter writer(&file);
        writer.setPageSize(QPageSize(QPageSize::A4));
        writer.setTitle(tr("Commissioning report"));
        writer.setCreator(QStringLiteral("CamBench"));
        writer.setResolution(150);
        document.setPageSize(QSizeF(writer.width(), writer.height()));
        document.print(&writer);
    }
    if (!file.commit())
        return Error::invalidData(tr("Cannot write the report to %1: %2").arg(path, file.errorString()));
    return success();
}

}  // namespace cambench
