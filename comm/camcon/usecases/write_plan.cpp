#include "write_plan.h"

#include <QSet>

namespace cambench::usecases {

namespace {

bool wasRead(const Project& project, ProjectPart part) {
    return project.readAt.parts.contains(part);
}

const CamProgram* findProgram(const Project& project, int number) {
    for (const CamProgram& program : project.programs) {
        if (program.number == number) return &program;
    }
    return nullptr;
}

// The device's user a project user stands for: the same number, else the
// same name.
const User* matchingUser(const QList<User>& onDevice, const User& wanted) {
    if (!wanted.number.isEmpty()) {
        for (const User& user : onDevice) {
            if (user.number == wanted.number) return &user;
        }
    }
    for (const User& user : onDevice) {
        if (user.name == wanted.name) return &user;
    }
    return nullptr;
}

void addTracks(WritePlan& plan, const CamProgram& program, const Project& onDevice) {
    const CamProgram* read = findProgram(onDevice, program.number);
    QSet<int> outputs;
    for (auto it = program.tracks.cbegin(); it != program.tracks.cend(); ++it) {
        if (!it->cams.isEmpty()) outputs.insert(it.key());
    }
    // Outputs without cams in the project are emptied on the device.
    if (wasRead(onDevice, ProjectPart::Device)) {
        for (int output = 1; output <= onDevice.device.outputs; ++output) outputs.insert(output);
    }
    if (read) {
        for (auto it = read->tracks.cbegin(); it != read->tracks.cend(); ++it)
            outputs.insert(it.key());
    }
    QList<int> sorted = outputs.values();
    std::sort(sorted.begin(), sorted.end());
    for (int output : sorted) {
        TrackWrite write;
        write.program = program.number;
        write.wanted = program.tracks.value(output);
        write.wanted.output = output;
        if (read) {
            Track believed = read->tracks.value(output);
            believed.output = output;
            write.believed = believed;
        }
        plan.tracks << write;
    }
}

void addUsers(WritePlan& plan, const Project& wanted, const Project& onDevice) {
    const bool usersRead = wasRead(onDevice, ProjectPart::Users);
    if (usersRead) plan.usersOnDevice = onDevice.users;
    for (const User& user : wanted.users) {
        UserWrite write;
        write.wanted = user;
        if (const User* device = usersRead ? matchingUser(onDevice.users, user) : nullptr) {
            write.deviceNumber = device->number;
            if (user.number.isEmpty()) write.wanted->number = device->number;
        }
        plan.users << write;
    }
}

void addPlcNetworks(WritePlan& plan, const Project& wanted, const Project& onDevice) {
    const bool read = wasRead(onDevice, ProjectPart::PlcNetworks);
    const auto find = [](const QList<PlcNetwork>& networks, int area, int number) {
        for (const PlcNetwork& network : networks) {
            if (network.area == area && network.number == number) return &network;
        }
        return static_cast<const PlcNetwork*>(nullptr);
    };
    const auto empty = [](int area, int number) {
        PlcNetwork network;
        network.area = area;
        network.number = number;
        return network;
    };
    for (const PlcNetwork& network : wanted.plcNetworks) {
        PlcWrite write{network, {}};
        if (read) {
            const PlcNetwork* device = find(onDevice.plcNetworks, network.area, network.number);
            write.believed = device ? *device : empty(network.area, network.number);
        }
        plan.plcNetworks << write;
    }
    // The project's PLC part replaces the device's: networks it does not
    // list are emptied.
    const bool projectHasPlc =
        !wanted.plcNetworks.isEmpty() || wanted.readAt.parts.contains(ProjectPart::PlcNetworks);
    if (!read || !projectHasPlc) return;
    for (const PlcNetwork& device : onDevice.plcNetworks) {
        if (device.isEmpty() || find(wanted.plcNetworks, device.area, device.number)) continue;
        plan.plcNetworks << PlcWrite{empty(device.area, device.number), device};
    }
}

// Analogue cams, programming program and EEPROM lock (table interface).
void addTableSections(WritePlan& plan, const Project& wanted, const Project& onDevice) {
    const bool analogueRead = wasRead(onDevice, ProjectPart::AnalogueCams);
    for (const AnalogueCamTrack& track : wanted.analogueCams) {
        AnalogueCamWrite write{track, {}};
        for (const AnalogueCamTrack& device : onDevice.analogueCams) {
            if (analogueRead && device.output == track.output) write.believed = device;
        }
        plan.analogueCams << write;
    }
    if (wanted.programmingProgram) {
        plan.programmingProgram = ProgrammingProgramWrite{*wanted.programmingProgram, {}};
        if (wasRead(onDevice, ProjectPart::ProgrammingProgram))
            plan.programmingProgram->believed = onDevice.programmingProgram;
    }
    if (wanted.eepromLock) {
        plan.eepromLock = EepromLockWrite{*wanted.eepromLock, {}};
        if (wasRead(onDevice, ProjectPart::EepromLock))
            plan.eepromLock->believed = onDevice.eepromLock;
    }
}

}  // namespace

int WritePlan::itemCount() const {
    return int(settings.size() + programNames.size() + tracks.size() + deadTimes.size() +
               deadTimeModes.size() + outputNames.size() + users.size() + plcNetworks.size() +
               analogueCams.size() + (programmingProgram ? 1 : 0) + (eepromLock ? 1 : 0));
}

WorkspaceItem itemOf(const TrackWrite& write) {
    return WorkspaceItem::track(write.program, write.wanted.output);
}

WorkspaceItem itemOf(const DeadTimeWrite& write) {
    return WorkspaceItem::deadTime(write.output);
}

WorkspaceItem itemOf(const DeadTimeModeWrite& write) {
    return WorkspaceItem::deadTimeMode(write.output);
}

WorkspaceItem itemOf(const UserWrite& write) {
    return write.row >= 0 ? WorkspaceItem::user(write.row)
                          : WorkspaceItem::deletedUser(write.deviceNumber);
}

WorkspaceItem itemOf(const PlcWrite& write) {
    return WorkspaceItem::plcNetwork(plcNetworkKey(write.wanted.area, write.wanted.number));
}

WorkspaceItem itemOf(const AnalogueCamWrite& write) {
    return WorkspaceItem::analogueCams(write.wanted.output);
}

WorkspaceItem programNameItem(const NameWrite& write) {
    return WorkspaceItem::programName(write.number);
}

WorkspaceItem outputNameItem(const NameWrite& write) {
    return WorkspaceItem::outputName(write.number);
}

QList<SettingsWrite> settingsGroups(const SystemSettings& wanted) {
    QList<SettingsWrite> groups;
    const auto groupOf = [&groups](const QString& name) -> SettingsWrite& {
        for (SettingsWrite& group : groups) {
            if (group.group == name) return group;
        }
        groups.append(SettingsWrite{name, {}});
        return groups.last();
    };
    for (const SettingSpec& spec : settingSpecs()) {
        const QString key = QLatin1String(spec.key);
        if (wanted.contains(key))
            groupOf(QLatin1String(spec.group)).wanted.insert(key, wanted.value(key));
    }
    for (auto it = wanted.cbegin(); it != wanted.cend(); ++it) {
        if (!findSetting(it.key())) groupOf(QStringLiteral("unknown")).wanted.insert(it.key(), *it);
    }
    return groups;
}

WritePlan planFromProject(const Project& wanted, const Project& onDevice) {
    WritePlan plan;
    if (wasRead(onDevice, ProjectPart::Settings)) plan.settingsOnDevice = onDevice.settings;
    // Read-only settings are the device's to decide: a project carries them
    // as read, they are not written.
    SystemSettings writable;
    for (auto it = wanted.settings.cbegin(); it != wanted.settings.cend(); ++it) {
        const SettingSpec* spec = findSetting(it.key());
        if (!spec || !spec->readOnly) writable.insert(it.key(), *it);
    }
    plan.settings = settingsGroups(writable);

    for (const CamProgram& program : wanted.programs) {
        const CamProgram* read = findProgram(onDevice, program.number);
        if (program.name.isEmpty() && !read) continue;
        NameWrite name{program.number, program.name, {}};
        if (read) name.believed = read->name;
        plan.programNames << name;
    }
    for (auto it = wanted.names.programs.cbegin(); it != wanted.names.programs.cend(); ++it) {
        if (findProgram(wanted, it.key())) continue;  // written with its program
        NameWrite name{it.key(), *it, {}};
        if (const CamProgram* read = findProgram(onDevice, it.key())) name.believed = read->name;
        plan.programNames << name;
    }
    for (const CamProgram& program : wanted.programs) addTracks(plan, program, onDevice);

    const bool deadTimesRead = wasRead(onDevice, ProjectPart::DeadTimes);
    for (auto it = wanted.deadTimes.cbegin(); it != wanted.deadTimes.cend(); ++it) {
        DeadTimeWrite write{it.key(), *it, {}};
        if (deadTimesRead) write.believed = onDevice.deadTimes.value(it.key(), 0);
        plan.deadTimes << write;
    }
    const bool modesRead = wasRead(onDevice, ProjectPart::DeadTimeModes);
    for (auto it = wanted.deadTimeModes.cbegin(); it != wanted.deadTimeModes.cend(); ++it) {
        DeadTimeModeWrite write{it.key(), *it, {}};
        if (modesRead) write.believed = onDevice.deadTimeModes.value(it.key());
        plan.deadTimeModes << write;
    }
    const bool namesRead = wasRead(onDevice, ProjectPart::OutputNames);
    for (auto it = wanted.names.outputs.cbegin(); it != wanted.names.outputs.cend(); ++it) {
        NameWrite write{it.key(), *it, {}};
        if (namesRead) write.believed = onDevice.names.outputs.value(it.key());
        plan.outputNames << write;
    }
    addUsers(plan, wanted, onDevice);
    addPlcNetworks(plan, wanted, onDevice);
    addTableSections(plan, wanted, onDevice);
    return plan;
}

}  // namespace cambench::usecases
