#include "project_io.h"

#include "workspace.h"

#include "ui/camcon/cameditor/cam_document.h"

namespace cambench {

Project projectFromWorkspace(const Workspace& workspace) {
    Project project;
    const CamDocument* cams = workspace.cams();
    const ProjectReadTimes& read = workspace.readTimes();
    project.device = workspace.info();
    if (workspace.infoFromDevice() && read.parts.contains(ProjectPart::Device))
        project.readAt.parts.insert(ProjectPart::Device, read.parts.value(ProjectPart::Device));
    for (int number : cams->editedPrograms()) {
        const CamProgram program = cams->program(number);
        project.programs.append(program);
        if (!program.name.isEmpty()) project.names.programs.insert(number, program.name);
        if (!cams->programEdited(number) && read.programs.contains(number))
            project.readAt.programs.insert(number, read.programs.value(number));
    }
    project.deadTimes = cams->deadTimes();
    project.minimumPulses = cams->minimumPulses();
    project.names.outputs = cams->names().outputs;
    if (workspace.outputSettingsEditCount() == 0) {
        for (ProjectPart part : {ProjectPart::DeadTimes, ProjectPart::OutputNames}) {
            if (read.parts.contains(part))
                project.readAt.parts.insert(part, read.parts.value(part));
        }
    }
    project.settings = workspace.settings().shown();
    if (workspace.settings().changedCount() == 0 && read.parts.contains(ProjectPart::Settings))
        project.readAt.parts.insert(ProjectPart::Settings, read.parts.value(ProjectPart::Settings));
    for (const UserCopies::EditedUser& user : workspace.users().rows())
        project.users.append(user.user);
    if (workspace.users().changedCount() == 0 && read.parts.contains(ProjectPart::Users))
        project.readAt.parts.insert(ProjectPart::Users, read.parts.value(ProjectPart::Users));
    project.plcNetworks = workspace.plc().shown().values();
    // As the Dead-time modes page shows them, edits included.
    // Stamped as read only when no mode differs from the device's, its dead
    // time (word 0, edited on either page) included.
    project.deadTimeModes = workspace.shownDeadTimeModes();
    if (project.deadTimeModes == workspace.deviceDeadTimeModes() &&
        read.parts.contains(ProjectPart::DeadTimeModes))
        project.readAt.parts.insert(ProjectPart::DeadTimeModes,
                                    read.parts.value(ProjectPart::DeadTimeModes));
    // The other table-interface sections, as their pages show them.
    project.analogueCams = workspace.analogueCams().shown().values();
    project.programmingProgram = workspace.programmingProgram().value();
    project.eepromLock = workspace.eepromLock().value();
    const auto stampIf = [&](ProjectPart part, bool edited) {
        if (!edited && read.parts.contains(part))
            project.readAt.parts.insert(part, read.parts.value(part));
    };
    stampIf(ProjectPart::AnalogueCams, !workspace.analogueCams().changedKeys().isEmpty());
    stampIf(ProjectPart::ProgrammingProgram, workspace.programmingProgram().isChanged());
    stampIf(ProjectPart::EepromLock, workspace.eepromLock().isChanged());
    if (workspace.plc().changedCount() == 0 && read.parts.contains(ProjectPart::PlcNetworks))
        project.readAt.parts.insert(ProjectPart::PlcNetworks,
                                    read.parts.value(ProjectPart::PlcNetworks));
    return project;
}

Project emptyProject(const DeviceInfo& capacities) {
    Project project;
    project.device = capacities;
    return project;
}

}  // namespace cambench
