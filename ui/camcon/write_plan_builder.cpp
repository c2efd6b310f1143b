#include "write_plan_builder.h"

#include "workspace.h"

#include "ui/camcon/cameditor/cam_document.h"

#include <QSet>

#include <algorithm>

namespace cambench {

namespace {

// Items of one program never read: all its outputs and its name.
QList<WorkspaceItem> wholeProgram(const Workspace& workspace, int program) {
    QList<WorkspaceItem> items{WorkspaceItem::programName(program)};
    for (int output = 1; output <= workspace.info().outputs; ++output)
        items << WorkspaceItem::track(program, output);
    return items;
}

QList<WorkspaceItem> expanded(const Workspace& workspace, const QList<WorkspaceItem>& items) {
    QList<WorkspaceItem> result;
    QSet<int> whole;
    for (const WorkspaceItem& item : items) {
        const bool camItem = item.kind == WorkspaceItem::Kind::Track ||
                             item.kind == WorkspaceItem::Kind::ProgramName;
        if (camItem && !workspace.cams()->hasDeviceCopy(item.program)) {
            if (!whole.contains(item.program)) result += wholeProgram(workspace, item.program);
            whole.insert(item.program);
            continue;
        }
        if (!result.contains(item)) result << item;
    }
    return result;
}

}  // namespace

QList<WorkspaceItem> changedItems(const Workspace& workspace) {
    QList<WorkspaceItem> items;
    for (const QString& key : workspace.settings().changedKeys())
        items << WorkspaceItem::setting(key);
    const CamDocument* cams = workspace.cams();
    for (int program : cams->editedPrograms()) {
        const std::optional<CamProgram> device = cams->deviceProgram(program);
        if (!device ? !cams->programName(program).isEmpty()
                    : cams->programName(program) != device->name)
            items << WorkspaceItem::programName(program);
    }
    for (const TrackDifference& d : cams->differences())
        items << WorkspaceItem::track(d.program, d.output);
    for (int output = 1; output <= workspace.info().deadTimeOutputs; ++output) {
        // Unknown on the device counts as 0 / no name, as in CamDocument::changedCount().
        if (cams->deadTime(output) != cams->deviceDeadTime(output).value_or(0))
            items << WorkspaceItem::deadTime(output);
    }
    for (int output = 1; output <= workspace.info().outputs; ++output) {
        if (cams->outputName(output) != cams->deviceOutputName(output).value_or(QString()))
            items << WorkspaceItem::outputName(output);
    }
    for (int i = 0; i < workspace.users().size(); ++i) {
        if (workspace.users().isChanged(i)) items << WorkspaceItem::user(i);
    }
    for (const QString& number : workspace.users().deletedNumbers())
        items << WorkspaceItem::deletedUser(number);
    for (int key : workspace.plc().changedKeys()) items << WorkspaceItem::plcNetwork(key);
    for (int output : workspace.deadTimeModes().changedKeys())
        items << WorkspaceItem::deadTimeMode(output);
    for (int output : workspace.analogueCams().changedKeys())
        items << WorkspaceItem::analogueCams(output);
    if (workspace.programmingProgram().isChanged()) items << WorkspaceItem::programmingProgram();
    if (workspace.eepromLock().isChanged()) items << WorkspaceItem::eepromLock();
    return items;
}

PlannedWrite planForItems(const Workspace& workspace, const QList<WorkspaceItem>& chosen) {
    const CamDocument* cams = workspace.cams();
    PlannedWrite planned;
    usecases::WritePlan& plan = planned.plan;
    SystemSettings settings;
    for (const WorkspaceItem& item :
         expanded(workspace, chosen.isEmpty() ? changedItems(workspace) : chosen)) {
        switch (item.kind) {
            case WorkspaceItem::Kind::Track: {
                usecases::TrackWrite write{item.program, cams->track(item.program, item.number),
                                           cams->deviceTrack(item.program, item.number)};
                plan.tracks << write;
                break;
            }
            case WorkspaceItem::Kind::ProgramName: {
                const std::optional<CamProgram> device = cams->deviceProgram(item.program);
                plan.programNames << usecases::NameWrite{
                    item.program, cams->programName(item.program),
                    device ? std::optional<QString>(device->name) : std::nullopt};
                break;
            }
            case WorkspaceItem::Kind::DeadTime:
                plan.deadTimes << usecases::DeadTimeWrite{item.number, cams->deadTime(item.number),
                                                          cams->deviceDeadTime(item.number)};
                break;
            case WorkspaceItem::Kind::OutputName:
                plan.outputNames << usecases::NameWrite{item.number, cams->outputName(item.number),
                                                        cams->deviceOutputName(item.number)};
                break;
            case WorkspaceItem::Kind::Setting:
                settings.insert(item.key,
                                workspace.settings().value(item.key).value_or(QVariant()));
                break;
            case WorkspaceItem::Kind::User: {
                if (item.number < 0 || item.number >= workspace.users().size()) break;
                const UserCopies::EditedUser edited = workspace.users().row(item.number);
                plan.users << usecases::UserWrite{edited.deviceNumber, edited.user, item.number};
                break;
            }
            case WorkspaceItem::Kind::DeletedUser:
                plan.users << usecases::UserWrite{item.key, std::nullopt, -1};
                break;
            case WorkspaceItem::Kind::DeadTimeMode: {
                plan.deadTimeModes << usecases::DeadTimeModeWrite{
                    item.number, workspace.deadTimeMode(item.number).value_or(OutputDeadTime{}),
                    workspace.deviceDeadTimeMode(item.number)};
                break;
            }
            case WorkspaceItem::Kind::AnalogueCams:
                if (const auto wanted = workspace.analogueCams().value(item.number))
                    plan.analogueCams << usecases::AnalogueCamWrite{
                        *wanted, workspace.analogueCams().deviceValue(item.number)};
                break;
            case WorkspaceItem::Kind::ProgrammingProgram:
                if (const auto wanted = workspace.programmingProgram().value())
                    plan.programmingProgram = usecases::ProgrammingProgramWrite{
                        *wanted, workspace.programmingProgram().deviceValue()};
                break;
            case WorkspaceItem::Kind::EepromLock:
                if (const auto wanted = workspace.eepromLock().value())
                    plan.eepromLock =
                        usecases::EepromLockWrite{*wanted, workspace.eepromLock().deviceValue()};
                break;
            case WorkspaceItem::Kind::PlcNetwork: {
                plan.plcNetworks << usecases::PlcWrite{
                    workspace.plc().value(item.number).value_or(PlcNetwork{}),
                    workspace.plc().deviceValue(item.number)};
                break;
            }
        }
    }
    if (!settings.isEmpty()) plan.settings = usecases::settingsGroups(settings);
    if (workspace.settings().known()) plan.settingsOnDevice = workspace.settings().device();
    if (workspace.users().known()) plan.usersOnDevice = workspace.users().device();
    return planned;
}

}  // namespace cambench
