#include "incoming_values.h"

#include "cam_text.h"
#include "plc_page.h"
#include "setting_field.h"
#include "ui/camcon/replace_edits_dialog.h"

#include "ui/camcon/cameditor/cam_document.h"

#include <QCoreApplication>
#include <QLocale>

#include <algorithm>

namespace cambench {

IncomingParts partsOf(const Project& incoming, ValueSource source) {
    IncomingParts parts;
    const ProjectReadTimes& read = incoming.readAt;
    for (const CamProgram& program : incoming.programs) {
        if (source == ValueSource::File || read.programs.contains(program.number))
            parts.programs << program.number;
    }
    if (source == ValueSource::File) {
        parts.outputSettings = true;
        parts.settings = !incoming.settings.isEmpty();
        parts.users = !incoming.users.isEmpty();
        parts.plc = !incoming.plcNetworks.isEmpty();
        return parts;
    }
    parts.outputSettings = read.parts.contains(ProjectPart::DeadTimes) ||
                           read.parts.contains(ProjectPart::OutputNames);
    parts.settings = read.parts.contains(ProjectPart::Settings);
    parts.users = read.parts.contains(ProjectPart::Users);
    parts.plc = read.parts.contains(ProjectPart::PlcNetworks);
    return parts;
}

QMap<EditSection, int> editsReplacedBy(const Workspace& workspace, const IncomingParts& parts) {
    QMap<EditSection, int> edits;
    const CamDocument* cams = workspace.cams();
    int camEdits = 0;
    for (const TrackDifference& d : cams->differences())
        camEdits += parts.programs.contains(d.program) ? 1 : 0;
    for (int program : parts.programs) {
        const std::optional<CamProgram> device = cams->deviceProgram(program);
        if (cams->programEdited(program) &&
            cams->programName(program) != (device ? device->name : QString()))
            ++camEdits;
    }
    if (camEdits > 0) edits.insert(EditSection::Cams, camEdits);
    if (parts.outputSettings && workspace.outputSettingsEditCount() > 0)
        edits.insert(EditSection::OutputSettings, workspace.outputSettingsEditCount());
    if (parts.settings && workspace.settings().changedCount() > 0)
        edits.insert(EditSection::Settings, workspace.settings().changedCount());
    if (parts.users && workspace.users().changedCount() > 0)
        edits.insert(EditSection::Users, workspace.users().changedCount());
    if (parts.plc && workspace.plc().changedCount() > 0)
        edits.insert(EditSection::Plc, workspace.plc().changedCount());
    return edits;
}

namespace {
void stamp(Workspace& workspace, const ProjectReadTimes& read, ProjectPart part) {
    const QDateTime time = read.parts.value(part);
    if (time.isValid()) workspace.setReadTime(part, time);
}
}  // namespace

void mergeIncoming(Workspace& workspace, const Project& incoming, ValueSource source,
                   const QSet<EditSection>& keepEdits) {
    const IncomingParts parts = partsOf(incoming, source);
    const bool fromDevice = source == ValueSource::Device;
    const ProjectReadTimes& read = incoming.readAt;
    if (fromDevice && read.parts.contains(ProjectPart::Device)) {
        workspace.setInfo(incoming.device, true);
        workspace.setCopiesFrom(incoming.device);
        stamp(workspace, read, ProjectPart::Device);
    }
    // The whole device read again (Read everything, Compare): nothing from
    // the other device is left to warn about.
    if (fromDevice && parts.settings && parts.outputSettings &&
        parts.programs.size() >= workspace.info().programs)
        workspace.clearOtherDeviceNote();
    if (parts.settings) {
        // A device's settings are its whole section; a file's name theirs.
        const bool keep = keepEdits.contains(EditSection::Settings);
        if (fromDevice)
            workspace.settings().mergeWhole(incoming.settings, keep);
        else
            workspace.settings().merge(incoming.settings, source, keep);
        if (fromDevice) stamp(workspace, read, ProjectPart::Settings);
    }
    for (const CamProgram& program : incoming.programs) {
        if (!parts.programs.contains(program.number)) continue;
        workspace.cams()->mergeProgram(program, fromDevice, keepEdits.contains(EditSection::Cams));
        const QDateTime time = read.programs.value(program.number);
        if (fromDevice && time.isValid()) workspace.setProgramReadTime(program.number, time);
    }
    // A project's minimum pulses are the PC's own notes: they come with the file.
    if (source == ValueSource::File) workspace.cams()->setMinimumPulses(incoming.minimumPulses);
    if (parts.outputSettings) {
        workspace.mergeOutputSettings(incoming.names.outputs, incoming.deadTimes, source,
                                      keepEdits.contains(EditSection::OutputSettings));
        for (ProjectPart part : {ProjectPart::DeadTimes, ProjectPart::OutputNames}) {
            if (fromDevice) stamp(workspace, read, part);
        }
    }
    if (parts.users) {
        workspace.users().merge(incoming.users, source, keepEdits.contains(EditSection::Users));
        if (fromDevice) stamp(workspace, read, ProjectPart::Users);
    }
    if (parts.plc) {
        workspace.plc().merge(Workspace::plcByKey(incoming.plcNetworks), source,
                              keepEdits.contains(EditSection::Plc));
        if (fromDevice) stamp(workspace, read, ProjectPart::PlcNetworks);
    }
    // Table interface only: a file's are edits (replacing the edits of the
    // outputs it names), a device's its copy (edits stay).
    if (!incoming.deadTimeModes.isEmpty()) {
        workspace.mergeDeadTimeModes(incoming.deadTimeModes, source, fromDevice);
        if (fromDevice) stamp(workspace, read, ProjectPart::DeadTimeModes);
    }
    // Analogue cams, programming program, EEPROM lock: a file's are edits,
    // a device's the copies (edits stay).
    QMap<int, AnalogueCamTrack> analogue;
    for (const AnalogueCamTrack& track : incoming.analogueCams)
        analogue.insert(track.output, track);
    workspace.analogueCams().merge(analogue, source, fromDevice);
    workspace.programmingProgram().merge(incoming.programmingProgram, source, fromDevice);
    workspace.eepromLock().merge(incoming.eepromLock, source, fromDevice);
    if (fromDevice) {
        for (ProjectPart part :
             {ProjectPart::AnalogueCams, ProjectPart::ProgrammingProgram, ProjectPart::EepromLock})
            stamp(workspace, read, part);
    }
}

namespace {

QString change(const QString& item, const QString& before, const QString& after) {
    return QCoreApplication::translate("cambench::DeviceChanges", "%1: %2 → %3")
        .arg(item, before, after);
}

}  // namespace

QStringList deviceChanges(const Workspace& workspace, const Project& incoming) {
    QStringList changes;
    const CamDocument* cams = workspace.cams();
    const IncomingParts parts = partsOf(incoming, ValueSource::Device);
    for (const CamProgram& program : incoming.programs) {
        const std::optional<CamProgram> before = cams->deviceProgram(program.number);
        if (!before || !parts.programs.contains(program.number)) continue;
        QList<int> outputs = before->tracks.keys() + program.tracks.keys();
        std::sort(outputs.begin(), outputs.end());
        outputs.erase(std::unique(outputs.begin(), outputs.end()), outputs.end());
        for (int output : outputs) {
            const Track old = before->tracks.value(output);
            const Track now = program.tracks.value(output);
            if (old.cams != now.cams)
                changes << change(
                    QCoreApplication::translate("cambench::DeviceChanges", "Program %1, output %2")
                        .arg(program.number)
                        .arg(output),
                    camsText(old), camsText(now));
        }
        if (before->name != program.name)
            changes << change(
                QCoreApplication::translate("cambench::DeviceChanges", "Program %1 name")
                    .arg(program.number),
                before->name, program.name);
    }
    if (parts.outputSettings && workspace.outputSettingsKnown()) {
        for (int output = 1; output <= workspace.info().outputs; ++output) {
            const qint32 oldTime = workspace.deviceDeadTime(output);
            if (incoming.deadTimes.contains(output) && incoming.deadTimes.value(output) != oldTime)
                changes << change(
                    QCoreApplication::translate("cambench::DeviceChanges", "Output %1 dead time")
                        .arg(output),
                    QString::number(oldTime / 10.0, 'f', 1),
                    QString::number(incoming.deadTimes.value(output) / 10.0, 'f', 1));
            const QString oldName = workspace.deviceOutputName(output);
            if (incoming.names.outputs.contains(output) &&
                incoming.names.outputs.value(output) != oldName)
                changes << change(
                    QCoreApplication::translate("cambench::DeviceChanges", "Output %1 name")
                        .arg(output),
                    oldName, incoming.names.outputs.value(output));
        }
    }
    if (parts.settings && workspace.settings().known()) {
        for (auto it = incoming.settings.cbegin(); it != incoming.settings.cend(); ++it) {
            const QVariant old = workspace.settings().deviceValue(it.key()).value_or(QVariant());
            const SettingSpec* spec = findSetting(it.key());
            if (spec && old.isValid() && old != it.value())
                changes << change(SettingField::labelText(*spec),
                                  SettingField::displayText(*spec, old),
                                  SettingField::displayText(*spec, it.value()));
        }
    }
    if (parts.users && workspace.users().known() && !(workspace.users().device() == incoming.users))
        changes << QCoreApplication::translate("cambench::DeviceChanges",
                                               "Users: the device's list of users changed.");
    if (parts.plc) {
        for (const PlcNetwork& network : incoming.plcNetworks) {
            const int key = Workspace::plcKey(network.area, network.number);
            const std::optional<PlcNetwork> old = workspace.plc().deviceValue(key);
            if (old && !(*old == network))
                changes << QCoreApplication::translate("cambench::DeviceChanges",
                                                       "PLC network %1 changed.")
                               .arg(PlcPage::networkName(network.area, network.number));
        }
    }
    return changes;
}

QMap<EditSection, QStringList> editedItemsReplacedBy(const Workspace& workspace,
                                                     const Project& incoming, ValueSource source) {
    const bool device = source == ValueSource::Device;
    const IncomingParts parts = partsOf(incoming, source);
    QMap<EditSection, QStringList> items;
    const CamDocument* cams = workspace.cams();
    for (const TrackDifference& d : cams->differences()) {
        if (!parts.programs.contains(d.program)) continue;
        Track arriving;
        for (const CamProgram& program : incoming.programs) {
            if (program.number == d.program) arriving = program.tracks.value(d.output);
        }
        items[EditSection::Cams]
            << (device ? QCoreApplication::translate(
                             "cambench::EditsReplaced",
                             "Program %1, output %2: yours %3; the device now holds %4")
                       : QCoreApplication::translate(
                             "cambench::EditsReplaced",
                             "Program %1, output %2: yours %3; the project holds %4"))
                   .arg(d.program)
                   .arg(d.output)
                   .arg(camsText(d.editedTrack), camsText(arriving));
    }
    if (parts.outputSettings) {
        const CamDocument* doc = workspace.cams();
        for (int output = 1; output <= workspace.info().outputs; ++output) {
            const qint32 mine = doc->deadTime(output);
            if (mine != workspace.deviceDeadTime(output) && incoming.deadTimes.contains(output))
                items[EditSection::OutputSettings]
                    << (device ? QCoreApplication::translate(
                                     "cambench::EditsReplaced",
                                     "Output %1 dead time: yours %2 ms; the device now holds %3 ms")
                               : QCoreApplication::translate(
                                     "cambench::EditsReplaced",
                                     "Output %1 dead time: yours %2 ms; the project holds %3 ms"))
                           .arg(output)
                           .arg(
                               QLocale().toString(mine / 10.0, 'f', 1),
                               QLocale().toString(incoming.deadTimes.value(output) / 10.0, 'f', 1));
            const QString name = doc->outputName(output);
            if (name != workspace.deviceOutputName(output) &&
                incoming.names.outputs.contains(output))
                items[EditSection::OutputSettings]
                    << (device ? QCoreApplication::translate(
                                     "cambench::EditsReplaced",
                                     "Output %1 name: yours \"%2\"; the device now holds \"%3\"")
                               : QCoreApplication::translate(
                                     "cambench::EditsReplaced",
                                     "Output %1 name: yours \"%2\"; the project holds \"%3\""))
                           .arg(output)
                           .arg(name, incoming.names.outputs.value(output));
        }
    }
    return items;
}

QSet<EditSection> sectionsAwaitingCarried(const Workspace& workspace, const Project& incoming) {
    const IncomingParts parts = partsOf(incoming, ValueSource::Device);
    QSet<EditSection> sections;
    for (int program : parts.programs) {
        if (workspace.awaitsCarriedProgram(program)) sections << EditSection::Cams;
    }
    if (parts.outputSettings && workspace.awaitsCarried(ProjectPart::DeadTimes) &&
        workspace.awaitsCarried(ProjectPart::OutputNames))
        sections << EditSection::OutputSettings;
    if (parts.settings && workspace.awaitsCarried(ProjectPart::Settings))
        sections << EditSection::Settings;
    if (parts.users && workspace.awaitsCarried(ProjectPart::Users)) sections << EditSection::Users;
    if (parts.plc && workspace.awaitsCarried(ProjectPart::PlcNetworks))
        sections << EditSection::Plc;
    return sections;
}

bool takeIncoming(QWidget* parent, Workspace& workspace, const Project& incoming,
                  ValueSource source) {
    QMap<EditSection, int> edits = editsReplacedBy(workspace, partsOf(incoming, source));
    // What the person carried from another device was decided on then.
    QSet<EditSection> keep;
    if (source == ValueSource::Device) keep = sectionsAwaitingCarried(workspace, incoming);
    for (EditSection section : keep) edits.remove(section);
    if (!edits.isEmpty()) {
        ReplaceEditsDialog dialog(edits, source, parent);
        dialog.setDetails(editedItemsReplacedBy(workspace, incoming, source));
        if (dialog.exec() != QDialog::Accepted) return false;
        keep += dialog.keptSections();
    }
    mergeIncoming(workspace, incoming, source, keep);
    return true;
}

}  // namespace cambench
