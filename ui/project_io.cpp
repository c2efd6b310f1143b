#include "project_io.h"

#include "workspace.h"

#include "ui/cameditor/cam_document.h"

namespace cambench {

Project projectFromWorkspace(const Workspace& workspace) {
    Project project;
    const CamDocument* cams = workspace.cams();
    project.device = workspace.info();
    for (int number : cams->editedPrograms()) {
        const CamProgram program = cams->program(number);
        if (!program.tracks.isEmpty() || !program.name.isEmpty()) project.programs.append(program);
    }
    project.deadTimes = cams->deadTimes();
    project.names.outputs = cams->names().outputs;
    for (const CamProgram& program : project.programs) {
        if (!program.name.isEmpty()) project.names.programs.insert(program.number, program.name);
    }
    project.settings = workspace.settings();
    for (const Workspace::EditedUser& user : workspace.users()) project.users.append(user.user);
    project.plcNetworks = workspace.plcNetworks().values();
    return project;
}

void loadProjectIntoWorkspace(Workspace& workspace, const Project& project) {
    workspace.setInfo(project.device, false);
    QMap<int, CamProgram> programs;
    for (const CamProgram& program : project.programs) programs.insert(program.number, program);
    workspace.cams()->loadOffline(programs, project.names, project.deadTimes);
    workspace.loadSettingsOffline(project.settings);
    workspace.loadUsersOffline(project.users);
    for (const PlcNetwork& network : project.plcNetworks) workspace.setPlcNetwork(network);
}

Project emptyProject(const DeviceInfo& capacities) {
    Project project;
    project.device = capacities;
    return project;
}

}  // namespace cambench
