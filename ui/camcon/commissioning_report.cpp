#include "commissioning_report.h"

#include "cam_text.h"
#include "milliseconds_text.h"
#include "plc_page.h"
#include "plc_symbol.h"
#include "print_diagram.h"
#include "setting_field.h"
#include "ui/change_marker.h"
#include "ui/report_pages.h"
#include "users_model.h"
#include "workspace.h"

#include "comm/camcon/usecases/value_text.h"
#include "ui/camcon/cameditor/cam_document.h"
#include "ui/camcon/cameditor/timing_text.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QLocale>
#include <QTextDocument>
#include <QUrl>

namespace cambench {

namespace {

// Outputs per diagram image: a taller image would not fit on one page.
constexpr int kOutputsPerDiagram = 32;
constexpr int kDiagramWidth = 1400;
// Shown this wide on the page (150 dpi): about the width of A4 inside its margins.
constexpr int kDiagramShownWidth = 900;

QString cell(const QString& text) {
    return QStringLiteral("<td>%1</td>").arg(text.toHtmlEscaped());
}

QString headerRow(const QStringList& titles) {
    QString row;
    for (const QString& title : titles)
        row += QStringLiteral("<th>%1</th>").arg(title.toHtmlEscaped());
    return QStringLiteral("<tr>%1</tr>").arg(row);
}

QString row(const QStringList& cells) {
    QString row;
    for (const QString& text : cells) row += cell(text);
    return QStringLiteral("<tr>%1</tr>").arg(row);
}

QString table(const QString& rows) {
    return QStringLiteral("<table border='1' cellspacing='0' cellpadding='3'>%1</table>").arg(rows);
}

QString paragraph(const QString& text) {
    return QStringLiteral("<p>%1</p>").arg(text.toHtmlEscaped());
}

QString heading(const QString& text) {
    return QStringLiteral("<h2>%1</h2>").arg(text.toHtmlEscaped());
}

// A value that differs from the device: marked, with the device's beside it.
QString marked(const QString& edited, bool changed, const QString& device) {
    if (!changed) return edited;
    return changedMarker() + CommissioningReport::tr("%1 (device: %2)").arg(edited, device);
}

class Builder {
public:
    Builder(QTextDocument& document, const Workspace& workspace,
            const CommissioningReport::Options& options)
        : m_document(document),
          m_workspace(workspace),
          m_cams(*workspace.cams()),
          m_options(options) {}

    QString build() {
        QString html = title();
        html += device();
        html += settings();
        html += outputs();
        html += deadTimeModes();
        html += tableSettings();
        html += analogueCams();
        for (int program = 0; program < m_workspace.info().programs; ++program)
            html += programSection(program);
        html += users();
        html += plc();
        return html;
    }

private:
    QString readTime(ProjectPart part) const {
        const QDateTime time = m_workspace.readTimes().parts.value(part);
        return time.isValid() ? reportTime(time) : QString();
    }

    // Whether the part was read from the device this report is of (a read
    // time is kept only for reads of the connected device).
    bool readFromDevice(ProjectPart part) const { return !readTime(part).isEmpty(); }
    static QString notRead() { return CommissioningReport::tr("not read from this device"); }

    // "Read from the device at …" or why not, for a section.
    QString source(ProjectPart part) const {
        const QString time = readTime(part);
        if (!time.isEmpty())
            return paragraph(CommissioningReport::tr("Read from the device at %1.").arg(time));
        return paragraph(
            m_workspace.infoFromDevice()
                ? CommissioningReport::tr("Not read from the device: the values are this PC's.")
                : CommissioningReport::tr("Offline project: the values are this PC's."));
    }

    QString title() const {
        QString html =
            QStringLiteral("<h1>%1</h1>").arg(CommissioningReport::tr("Commissioning report"));
        html += paragraph(
            CommissioningReport::tr("Created %1 with CamBench %2")
                .arg(reportTime(QDateTime::currentDateTime()), QStringLiteral(CAMBENCH_VERSION)));
        const int changes = m_workspace.changedCount();
        html += paragraph(
            changes > 0
                ? CommissioningReport::tr(
                      "%n value(s) in this report are edited on this PC and NOT written to the "
                      "device; they are marked %1 and show the device's value beside them.",
                      nullptr, changes)
                      .arg(changedMarker().trimmed())
            : m_workspace.infoFromDevice()
                ? CommissioningReport::tr(
                      "Every value in this report is what the device held when it was read.")
                : CommissioningReport::tr(
                      "Offline project: nothing in this report was read from a device."));
        return html;
    }

    QString device() const {
        const DeviceInfo& info = m_workspace.info();
        QString rows;
        if (m_workspace.infoFromDevice()) {
            rows += row({CommissioningReport::tr("Firmware (EPROM date)"), info.epromDate});
            rows +=
                row({CommissioningReport::tr("Device number"), QString::number(info.deviceNumber)});
            rows +=
                row({CommissioningReport::tr("Identity read at"), readTime(ProjectPart::Device)});
        } else {
            rows += row(
                {CommissioningReport::tr("Source"), CommissioningReport::tr("offline project")});
            if (!m_workspace.projectPath().isEmpty())
                rows += row({CommissioningReport::tr("Project file"), m_workspace.projectPath()});
        }
        rows += row({CommissioningReport::tr("Outputs / inputs"),
                     QStringLiteral("%1 / %2").arg(info.outputs).arg(info.inputs)});
        rows += row({CommissioningReport::tr("Programs"),
                     CommissioningReport::tr("0 … %1").arg(info.programs - 1)});
        rows += row({CommissioningReport::tr("Position range"),
                     QStringLiteral("%1 … %2").arg(info.minPosition).arg(info.maxPosition)});
        return heading(CommissioningReport::tr("Device")) + table(rows);
    }

    QString settings() const {
        QString rows;
        const SystemSettings edited = m_workspace.settings().shown();
        // A device value only where it was read from the connected device.
        const SystemSettings device = readFromDevice(ProjectPart::Settings)
                                          ? m_workspace.settings().device()
                                          : SystemSettings{};
        for (const SettingSpec& spec : settingSpecs()) {
            const QString key = QString::fromLatin1(spec.key);
            if (!edited.contains(key)) continue;
            const auto text = [&spec](const QVariant& value) {
                return SettingField::textWithUnit(spec, value);
            };
            const bool changed = !device.contains(key) || device.value(key) != edited.value(key);
            rows += row({SettingField::labelText(spec),
                         marked(text(edited.value(key)), changed,
                                device.contains(key) ? text(device.value(key)) : notRead())});
        }
        QString html = heading(CommissioningReport::tr("Settings")) + source(ProjectPart::Settings);
        return html + (rows.isEmpty() ? paragraph(CommissioningReport::tr("Settings not read."))
                                      : table(rows));
    }

    QString outputs() const {
        QString rows =
            headerRow({CommissioningReport::tr("Output"), CommissioningReport::tr("Name"),
                       CommissioningReport::tr("Dead time")});
        const DeviceInfo& info = m_workspace.info();
        // Over the device's outputs; dead times where it has them.
        for (int output = 1; output <= info.outputs; ++output) {
            const std::optional<QString> deviceName = readFromDevice(ProjectPart::OutputNames)
                                                          ? m_cams.deviceOutputName(output)
                                                          : std::nullopt;
            const QString name = m_cams.outputName(output);
            QString deadTime = QStringLiteral("—");
            if (output <= info.deadTimeOutputs) {
                const std::optional<qint32> device = readFromDevice(ProjectPart::DeadTimes)
                                                         ? m_cams.deviceDeadTime(output)
                                                         : std::nullopt;
                deadTime = marked(millisecondsText(m_cams.deadTime(output)),
                                  device && *device != m_cams.deadTime(output),
                                  device ? millisecondsText(*device) : QString());
            }
            rows += row(
                {QString::number(output),
                 marked(name, deviceName && *deviceName != name, deviceName.value_or(QString())),
                 deadTime});
        }
        return heading(CommissioningReport::tr("Outputs and dead times")) +
               source(ProjectPart::DeadTimes) + table(rows);
    }

    // Table interface only: absent when neither read nor in the project.
    QString deadTimeModes() const {
        const DeadTimeModes modes = m_workspace.shownDeadTimeModes();
        if (modes.isEmpty()) return {};
        const DeadTimeModes onDevice = readFromDevice(ProjectPart::DeadTimeModes)
                                           ? m_workspace.deviceDeadTimeModes()
                                           : DeadTimeModes{};
        QString rows =
            headerRow({CommissioningReport::tr("Output"), CommissioningReport::tr("Mode"),
                       CommissioningReport::tr("Dead time"), CommissioningReport::tr("Switch-on"),
                       CommissioningReport::tr("Switch-off / time")});
        const auto modeName = [](DeadTimeMode mode) {
            switch (mode) {
                case DeadTimeMode::Normal:
                    return CommissioningReport::tr("Normal");
                case DeadTimeMode::SeparateOnOff:
                    return CommissioningReport::tr("On/off");
                case DeadTimeMode::PathTime:
                    return CommissioningReport::tr("Path-time");
            }
            return QString();
        };
        for (auto it = modes.cbegin(); it != modes.cend(); ++it) {
            const bool known = onDevice.contains(it.key());
            const OutputDeadTime device = onDevice.value(it.key());
            const auto cell = [&](const QString& edited, bool differs, const QString& was) {
                return marked(edited, !known || differs, known ? was : notRead());
            };
            rows += row(
                {QString::number(it.key()),
                 cell(modeName(it->mode), it->mode != device.mode, modeName(device.mode)),
                 cell(millisecondsText(it->normal), it->normal != device.normal,
                      millisecondsText(device.normal)),
                 cell(millisecondsText(it->on), it->on != device.on, millisecondsText(device.on)),
                 cell(millisecondsText(it->off), it->off != device.off,
                      millisecondsText(device.off))});
        }
        return heading(CommissioningReport::tr("Dead-time modes")) +
               source(ProjectPart::DeadTimeModes) + table(rows);
    }

    // The programming program and the EEPROM lock (table interface only):
    // absent when neither read nor in the project.
    QString tableSettings() const {
        const std::optional<ProgrammingProgram> programming =
            m_workspace.programmingProgram().value();
        const std::optional<bool> lock = m_workspace.eepromLock().value();
        if (!programming && !lock) return {};
        QString rows;
        if (programming) {
            const std::optional<ProgrammingProgram> device =
                readFromDevice(ProjectPart::ProgrammingProgram)
                    ? m_workspace.programmingProgram().deviceValue()
                    : std::nullopt;
            rows += row({CommissioningReport::tr("Programming program"),
                         marked(usecases::programmingProgramText(*programming),
                                m_workspace.programmingProgram().isChanged(),
                                device ? usecases::programmingProgramText(*device) : notRead())});
        }
        if (lock) {
            const std::optional<bool> device = readFromDevice(ProjectPart::EepromLock)
                                                   ? m_workspace.eepromLock().deviceValue()
                                                   : std::nullopt;
            rows +=
                row({CommissioningReport::tr("EEPROM lock"),
                     marked(usecases::eepromLockText(*lock), m_workspace.eepromLock().isChanged(),
                            device ? usecases::eepromLockText(*device) : notRead())});
        }
        return heading(CommissioningReport::tr("Programming program and EEPROM lock")) +
               source(ProjectPart::ProgrammingProgram) + table(rows);
    }

    QString analogueCams() const {
        QString rows = headerRow(
            {CommissioningReport::tr("Analogue output"), CommissioningReport::tr("Base points")});
        bool any = false;
        for (int output = 1; output <= kAnalogueOutputs; ++output) {
            const std::optional<AnalogueCamTrack> track = m_workspace.analogueCams().value(output);
            if (!track) continue;
            any = true;
            const std::optional<AnalogueCamTrack> device =
                readFromDevice(ProjectPart::AnalogueCams)
                    ? m_workspace.analogueCams().deviceValue(output)
                    : std::nullopt;
            rows += row({QString::number(output),
                         marked(usecases::analogueCamsText(*track), !device || *device != *track,
                                device ? usecases::analogueCamsText(*device) : notRead())});
        }
        if (!any) return {};
        return heading(CommissioningReport::tr("Analogue cams")) +
               source(ProjectPart::AnalogueCams) + table(rows);
    }

    QString programSection(int number) {
        const CamProgram program = m_cams.program(number);
        const bool known = m_cams.hasDeviceCopy(number);
        const bool present = m_cams.editedPrograms().contains(number);
        QString title =
            program.name.isEmpty()
                ? CommissioningReport::tr("Program %1").arg(number)
                : CommissioningReport::tr("Program %1: %2").arg(number).arg(program.name);
        QString html = heading(title);
        if (!present)
            return html + paragraph(CommissioningReport::tr(
                              "Not read from the device: its content is unknown."));
        const QDateTime read = m_workspace.readTimes().programs.value(number);
        if (!known) {
            html += paragraph(CommissioningReport::tr(
                "Not read from the device: these cams exist on this PC only."));
        } else if (read.isValid()) {
            html += paragraph(
                CommissioningReport::tr("Read from the device at %1.").arg(reportTime(read)));
        }
        if (program.tracks.isEmpty()) return html + paragraph(CommissioningReport::tr("No cams."));
        const int outputs = m_workspace.info().outputs;
        for (int first = 1; first <= outputs; first += kOutputsPerDiagram) {
            const int last = std::min(outputs, first + kOutputsPerDiagram - 1);
            const QString resource = QStringLiteral("%1diagram-%2-%3.png")
                                         .arg(m_options.resourcePrefix)
                                         .arg(number)
                                         .arg(first);
            m_document.addResource(QTextDocument::ImageResource, QUrl(resource),
                                   printDiagram(m_cams, number, first, last, kDiagramWidth));
            html += QStringLiteral("<p><img src='%1' width='%2'></p>")
                        .arg(resource)
                        .arg(kDiagramShownWidth);
        }
        QString rows = headerRow(
            {CommissioningReport::tr("Output"), CommissioningReport::tr("Cams (on–off)")});
        for (int output = 1; output <= outputs; ++output) {
            const Track track = m_cams.track(number, output);
            const std::optional<Track> device = m_cams.deviceTrack(number, output);
            if (track.cams.isEmpty() && (!device || device->cams.isEmpty())) continue;
            const bool changed = known && device && device->cams != track.cams;
            rows += row({QString::number(output),
                         marked(camsText(track), changed, device ? camsText(*device) : QString())});
        }
        return html + table(rows) + timing(program);
    }

    // Where the outputs switch at the speed asked for, as the cam page's
    // timing view draws it (model/camcon/cam_timing.h).
    QString timing(const CamProgram& program) const {
        if (!m_options.timingSpeed) return {};
        const Axis axis = m_cams.axis();
        const double v = toPositionsPerSecond(*m_options.timingSpeed, axis);
        const QList<OutputTiming> outputs = timeProgram(
            program, deadTimesAsModes(m_cams.deadTimes(), m_workspace.shownDeadTimeModes()), v,
            axis, m_cams.minimumPulses());
        QString rows = headerRow(
            {CommissioningReport::tr("Output"), CommissioningReport::tr("Dead time on / off"),
             CommissioningReport::tr("Shift on / off"), CommissioningReport::tr("Shortest cam"),
             CommissioningReport::tr("Minimum pulse"), CommissioningReport::tr("Limit")});
        QStringList warnings;
        const QLocale locale;
        for (const OutputTiming& t : outputs) {
            const qint32 pulse = m_cams.minimumPulses().value(t.output);
            rows += row(
                {QString::number(t.output),
                 QStringLiteral("%1 / %2").arg(durationText(t.onDeadTimeMs),
                                               durationText(t.offDeadTimeMs)),
                 CommissioningReport::tr("%1 / %2 positions")
                     .arg(locale.toString(t.shiftOn, 'f', 1), locale.toString(t.shiftOff, 'f', 1)),
                 t.shortestDurationMs ? durationText(*t.shortestDurationMs)
                                      : CommissioningReport::tr("standing still"),
                 pulse > 0 ? durationText(pulse / 10.0) : QStringLiteral("—"),
                 t.firstLimit ? timingProblemText(t.output, *t.firstLimit, axis)
                              : CommissioningReport::tr("none")});
            for (const TimingProblem& problem : t.problems)
                warnings << timingProblemText(t.output, problem, axis);
        }
        QString html = QStringLiteral("<h3>%1</h3>")
                           .arg(CommissioningReport::tr("Timing at %1")
                                    .arg(speedText(v, axis))
                                    .toHtmlEscaped());
        html += paragraph(CommissioningReport::tr(
            "Each edge switches early by speed × its dead time, so that the actuator acts at the "
            "programmed position. Dead times as in this report (edits included)."));
        html += table(rows);
        if (!warnings.isEmpty())
            html += paragraph(CommissioningReport::tr("Warnings at this speed: %1")
                                  .arg(warnings.join(QLatin1Char(' '))));
        return html;
    }

    QString users() const {
        QString html = heading(CommissioningReport::tr("Users")) + source(ProjectPart::Users);
        if (m_workspace.users().size() == 0 && m_workspace.users().deletedNumbers().isEmpty())
            return html + paragraph(CommissioningReport::tr("No users."));
        html += paragraph(
            CommissioningReport::tr("User numbers are access codes: they are not printed."));
        QString rows =
            headerRow({CommissioningReport::tr("Name"), CommissioningReport::tr("Number"),
                       CommissioningReport::tr("Rights")});
        for (int i = 0; i < m_workspace.users().size(); ++i) {
            const User user = m_workspace.users().row(i).user;
            const QString name =
                m_workspace.users().isChanged(i) ? changedMarker() + user.name : user.name;
            rows += row({name, user.maskedNumber(), UsersModel::rightsText(user.rights)});
        }
        for (const QString& number : m_workspace.users().deletedNumbers()) {
            if (const std::optional<User> user = m_workspace.users().deviceUser(number))
                rows += row({changedMarker() + user->name, user->maskedNumber(),
                             CommissioningReport::tr("deleted on this PC, still on the device")});
        }
        return html + table(rows);
    }

    QString plc() const {
        QString html =
            heading(CommissioningReport::tr("PLC networks")) + source(ProjectPart::PlcNetworks);
        const QMap<int, PlcNetwork> networks = m_workspace.plc().shown();
        if (networks.isEmpty())
            return html + paragraph(CommissioningReport::tr("No PLC networks read or edited."));
        QString rows = headerRow(
            {CommissioningReport::tr("Network"), CommissioningReport::tr("Value"),
             CommissioningReport::tr("Reset"), CommissioningReport::tr("Symbols by path")});
        for (auto it = networks.cbegin(); it != networks.cend(); ++it) {
            QStringList paths;
            for (int path = 0; path < PlcNetwork::kPaths; ++path) {
                QStringList symbols;
                for (int i = 0; i < PlcNetwork::kSymbolsPerPath; ++i) {
                    const QString symbol =
                        plcsymbol::display(it->symbols[path * PlcNetwork::kSymbolsPerPath + i]);
                    symbols << (symbol.isEmpty() ? QStringLiteral("·") : symbol);
                }
                paths << symbols.join(QLatin1Char(' '));
            }
            const QString name = PlcPage::networkName(it->area, it->number);
            rows += row({m_workspace.plc().isChanged(it.key()) ? changedMarker() + name : name,
                         QString::number(it->value), plcsymbol::editText(it->reset),
                         paths.join(QStringLiteral(" | "))});
        }
        return html + table(rows);
    }

    QTextDocument& m_document;
    const Workspace& m_workspace;
    const CamDocument& m_cams;
    CommissioningReport::Options m_options;
};

}  // namespace

void CommissioningReport::build(QTextDocument& document, const Workspace& workspace,
                                const Options& options) {
    document.setHtml(Builder(document, workspace, options).build());
}

Status CommissioningReport::write(const QString& path, const Workspace& workspace,
                                  const Options& options) {
    QTextDocument document;
    build(document, workspace, options);
    return writeReportPdf(path, document, tr("Commissioning report"), tr("Page %1 of %2"));
}

QString CommissioningReport::html(QTextDocument& document, const Workspace& workspace,
                                  const Options& options) {
    return Builder(document, workspace, options).build();
}

}  // namespace cambench
