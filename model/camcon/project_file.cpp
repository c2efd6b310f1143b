#include "project_file.h"

#include "cam_validation.h"
#include "data_validation.h"
#include "device_info_json.h"
#include "model/atomic_file.h"
#include "model/camcon/camcon_family_id.h"
#include "model/file_read.h"
#include "model/json_file.h"
#include "model/json_reader.h"
#include "plc_file.h"
#include "settings_file.h"
#include "table_sections_json.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QSet>

#include <limits>

namespace cambench {

namespace {

const JsonFileType kProjectFile{"cambench-project", kProjectFormatVersion, "project",
                                camconFamilyId.latin1()};

// Outputs the user access table can address (32 bytes of bits).
constexpr int kUserAccessOutputs = 256;

QString key(const char* text) {
    return QString::fromLatin1(text);
}

// The JSON names of the parts in "readAt".
struct PartName {
    ProjectPart part;
    const char* name;
};
const PartName kPartNames[] = {
    {ProjectPart::Device, "device"},
    {ProjectPart::Settings, "settings"},
    {ProjectPart::DeadTimes, "deadTimes"},
    {ProjectPart::OutputNames, "outputNames"},
    {ProjectPart::Users, "users"},
    {ProjectPart::PlcNetworks, "plcNetworks"},
    {ProjectPart::DeadTimeModes, "deadTimeModes"},
    {ProjectPart::AnalogueCams, "analogueCams"},
    {ProjectPart::ProgrammingProgram, "programmingProgram"},
    {ProjectPart::EepromLock, "eepromLock"},
};

QString isoTime(const QDateTime& time) {
    return time.toUTC().toString(Qt::ISODateWithMs);
}

// ---- writing ----

QJsonObject trackToJson(const Track& track) {
    QJsonArray cams;
    for (const Cam& cam : track.cams) cams.append(QJsonArray{cam.on, cam.off});
    return {{key("output"), track.output}, {key("cams"), cams}};
}

QJsonObject programToJson(const CamProgram& program) {
    QJsonArray tracks;
    for (const Track& track : program.tracks) tracks.append(trackToJson(track));
    return {{key("number"), program.number}, {key("name"), program.name}, {key("tracks"), tracks}};
}

template <class Map>
QJsonArray numberedToJson(const Map& map, const char* numberKey, const char* valueKey) {
    QJsonArray array;
    for (auto it = map.cbegin(); it != map.cend(); ++it)
        array.append(QJsonObject{{key(numberKey), it.key()}, {key(valueKey), *it}});
    return array;
}

QJsonObject userToJson(const User& user, bool withNumber) {
    QJsonArray outputs;
    for (int i = 0; i < user.outputAccess.size(); ++i) {
        if (user.outputAccess.at(i)) outputs.append(i + 1);
    }
    QJsonObject object{{key("name"), user.name},
                       {key("allOutputs"), user.allOutputs},
                       {key("rights"), qint64(user.rights)},
                       {key("outputs"), outputs}};
    if (withNumber && !user.number.isEmpty()) object.insert(key("number"), user.number);
    return object;
}

QJsonObject readTimesToJson(const ProjectReadTimes& readAt) {
    QJsonObject object;
    for (const PartName& part : kPartNames) {
        const auto time = readAt.parts.constFind(part.part);
        if (time != readAt.parts.cend()) object.insert(key(part.name), isoTime(*time));
    }
    QJsonArray programs;
    for (auto it = readAt.programs.cbegin(); it != readAt.programs.cend(); ++it)
        programs.append(QJsonObject{{key("program"), it.key()}, {key("time"), isoTime(*it)}});
    object.insert(key("programs"), programs);
    return object;
}

// ---- reading ----

// Reads the top-level sections in an order that lets later ones be checked
// against earlier ones (outputs and programs against the device). Only the
// structure is checked here: values a device could hold load as they are
// and validateProject() warns about them.
class ProjectReader {
public:
    Result<Project> read(const QJsonObject& root) {
        Project project;
        project.device = readDeviceInfo(m_r, m_r.object(root, {}, key("device")), key("device"));
        project.settings =
            settingsFromJson(m_r, m_r.object(root, {}, key("settings")), key("settings"));
        project.programs = readPrograms(m_r.array(root, {}, key("programs")), project.device);
        project.deadTimes = readDeadTimes(m_r.array(root, {}, key("deadTimes")), project.device);
        project.names.outputs = readNames(m_r.array(root, {}, key("outputNames")), "outputNames",
                                          "output", 1, project.device.outputs);
        project.names.programs = readNames(m_r.array(root, {}, key("programNames")), "programNames",
                                           "program", 0, project.device.programs - 1);
        project.users = readUsers(m_r.array(root, {}, key("users")));
        project.plcNetworks =
            plcNetworksFromJson(m_r, m_r.array(root, {}, key("plcNetworks")), key("plcNetworks"));
        // Files from before dead-time modes were carried have none.
        if (root.contains(key("deadTimeModes"))) {
            project.deadTimeModes =
                readDeadTimeModes(m_r.array(root, {}, key("deadTimeModes")), project.device);
        }
        // The other table-interface sections, equally optional.
        if (root.contains(key("analogueCams"))) {
            project.analogueCams = analogueCamsFromJson(
                m_r, m_r.array(root, {}, key("analogueCams")), key("analogueCams"));
        }
        if (root.contains(key("programmingProgram"))) {
            project.programmingProgram = programmingProgramFromJson(
                m_r, m_r.object(root, {}, key("programmingProgram")), key("programmingProgram"));
        }
        if (root.contains(key("eepromLock"))) {
            project.eepromLock =
                m_r.boolean(root, {}, key("eepromLock"),
                            QCoreApplication::translate("cambench::model", "EEPROM lock"));
        }
        if (root.contains(key("minimumPulses"))) {
            project.minimumPulses =
                readMinimumPulses(m_r.array(root, {}, key("minimumPulses")), project.device);
        }
        if (root.contains(key("readAt")))
            project.readAt = readTimes(m_r.object(root, {}, key("readAt")));
        if (m_r.failed()) return Error::invalidData(m_r.problem() + QLatin1Char('.'));
        return project;
    }

private:
    QList<CamProgram> readPrograms(const QJsonArray& array, const DeviceInfo& device) {
        QList<CamProgram> programs;
        QSet<int> seen;
        for (int i = 0; i < array.size() && !m_r.failed(); ++i) {
            const QString path = JsonReader::element(key("programs"), i);
            const QJsonObject object = m_r.objectValue(array.at(i), path);
            CamProgram program;
            program.number =
                int(m_r.integer(object, path, key("number"),
                                QCoreApplication::translate("cambench::model", "program number"), 0,
                                device.programs - 1));
            program.name =
                m_r.string(object, path, key("name"),
                           QCoreApplication::translate("cambench::model", "program name"));
            if (!m_r.failed() && seen.contains(program.number)) {
                m_r.fail(JsonReader::member(path, key("number")),
                         QCoreApplication::translate("cambench::model", "program %1 appears twice")
                             .arg(program.number));
            }
            seen.insert(program.number);
            const QJsonArray tracks = m_r.array(object, path, key("tracks"));
            for (int j = 0; j < tracks.size() && !m_r.failed(); ++j) {
                const QString trackPath =
                    JsonReader::element(JsonReader::member(path, key("tracks")), j);
                const Track track = readTrack(tracks.at(j), trackPath, device);
                if (!m_r.failed() && program.tracks.contains(track.output)) {
                    m_r.fail(
                        JsonReader::member(trackPath, key("output")),
                        QCoreApplication::translate("cambench::model", "output %1 appears twice")
                            .arg(track.output));
                }
                program.tracks.insert(track.output, track);
            }
            programs << program;
        }
        return programs;
    }

    Track readTrack(const QJsonValue& value, const QString& path, const DeviceInfo& device) {
        const QJsonObject object = m_r.objectValue(value, path);
        Track track;
        track.output = int(m_r.integer(object, path, key("output"),
                                       QCoreApplication::translate("cambench::model", "output"), 1,
                                       device.outputs));
        const QJsonArray cams = m_r.array(object, path, key("cams"));
        const QString camsPath = JsonReader::member(path, key("cams"));
        for (int k = 0; k < cams.size() && !m_r.failed(); ++k) {
            const QString camPath = JsonReader::element(camsPath, k);
            const QJsonArray pair = m_r.arrayValue(cams.at(k), camPath);
            if (!m_r.failed() && pair.size() != 2) {
                m_r.fail(camPath,
                         QCoreApplication::translate("cambench::model",
                                                     "a cam is a pair [switch-on point, "
                                                     "switch-off point], this has %1 values")
                             .arg(pair.size()));
            }
            Cam cam;
            cam.on = qint32(m_r.integerValue(
                pair.at(0), camPath,
                QCoreApplication::translate("cambench::model", "switch-on point")));
            cam.off = qint32(m_r.integerValue(
                pair.at(1), camPath,
                QCoreApplication::translate("cambench::model", "switch-off point")));
            track.cams << cam;
        }
        return track;
    }

    DeadTimes readDeadTimes(const QJsonArray& array, const DeviceInfo& device) {
        return readOutputValues(array, "deadTimes", "deadTime",
                                QCoreApplication::translate("cambench::model", "dead time"),
                                device.deadTimeOutputs);
    }

    MinimumPulses readMinimumPulses(const QJsonArray& array, const DeviceInfo& device) {
        return readOutputValues(array, "minimumPulses", "minimumPulse",
                                QCoreApplication::translate("cambench::model", "minimum pulse"),
                                device.outputs, 0);
    }

    // [{"output": n, valueKey: v}, ...], each output at most once.
    QMap<int, qint32> readOutputValues(const QJsonArray& array, const char* member,
                                       const char* valueKey, const QString& what, int outputs,
                                       qint64 min = std::numeric_limits<qint32>::min()) {
        QMap<int, qint32> values;
        for (int i = 0; i < array.size() && !m_r.failed(); ++i) {
            const QString path = JsonReader::element(key(member), i);
            const QJsonObject object = m_r.objectValue(array.at(i), path);
            const int output = int(
                m_r.integer(object, path, key("output"),
                            QCoreApplication::translate("cambench::model", "output"), 1, outputs));
            const qint32 value = qint32(m_r.integer(object, path, key(valueKey), what, min));
            if (!m_r.failed() && values.contains(output)) {
                m_r.fail(JsonReader::member(path, key("output")),
                         QCoreApplication::translate("cambench::model", "output %1 appears twice")
                             .arg(output));
            }
            values.insert(output, value);
        }
        return values;
    }

    DeadTimeModes readDeadTimeModes(const QJsonArray& array, const DeviceInfo& device) {
        DeadTimeModes modes;
        for (int i = 0; i < array.size() && !m_r.failed(); ++i) {
            const QString path = JsonReader::element(key("deadTimeModes"), i);
            const QJsonObject object = m_r.objectValue(array.at(i), path);
            const int output =
                int(m_r.integer(object, path, key("output"),
                                QCoreApplication::translate("cambench::model", "output"), 1,
                                device.deadTimeOutputs));
            const QString modeKey =
                m_r.string(object, path, key("mode"),
                           QCoreApplication::translate("cambench::model", "dead-time mode"));
            OutputDeadTime deadTime;
            const std::optional<DeadTimeMode> mode = deadTimeModeFromKey(modeKey);
            if (!m_r.failed() && !mode) {
                m_r.fail(
                    JsonReader::member(path, key("mode")),
                    QCoreApplication::translate(
                        "cambench::model", "unknown mode \"%1\"; use normal, on/off or path-time")
                        .arg(modeKey));
            }
            deadTime.mode = mode.value_or(DeadTimeMode::Normal);
            deadTime.normal =
                qint32(m_r.integer(object, path, key("deadTime"),
                                   QCoreApplication::translate("cambench::model", "dead time")));
            deadTime.on = qint32(
                m_r.integer(object, path, key("on"),
                            QCoreApplication::translate("cambench::model", "switch-on dead time")));
            deadTime.off = qint32(m_r.integer(
                object, path, key("off"),
                QCoreApplication::translate("cambench::model", "switch-off dead time")));
            if (!m_r.failed() && modes.contains(output)) {
                m_r.fail(JsonReader::member(path, key("output")),
                         QCoreApplication::translate("cambench::model", "output %1 appears twice")
                             .arg(output));
            }
            modes.insert(output, deadTime);
        }
        return modes;
    }

    QMap<int, QString> readNames(const QJsonArray& array, const char* section,
                                 const char* numberKey, int min, int max) {
        QMap<int, QString> names;
        for (int i = 0; i < array.size() && !m_r.failed(); ++i) {
            const QString path = JsonReader::element(key(section), i);
            const QJsonObject object = m_r.objectValue(array.at(i), path);
            const int number =
                int(m_r.integer(object, path, key(numberKey), key(numberKey), min, max));
            const QString name = m_r.string(object, path, key("name"),
                                            QCoreApplication::translate("cambench::model", "name"));
            if (!m_r.failed() && names.contains(number)) {
                m_r.fail(JsonReader::member(path, key(numberKey)),
                         QCoreApplication::translate("cambench::model", "%1 %2 appears twice")
                             .arg(key(numberKey))
                             .arg(number));
            }
            names.insert(number, name);
        }
        return names;
    }

    QList<User> readUsers(const QJsonArray& array) {
        QList<User> users;
        for (int i = 0; i < array.size() && !m_r.failed(); ++i) {
            const QString path = JsonReader::element(key("users"), i);
            const QJsonObject object = m_r.objectValue(array.at(i), path);
            User user;
            user.name = m_r.string(object, path, key("name"),
                                   QCoreApplication::translate("cambench::model", "user name"));
            // Saved without numbers unless asked for (ProjectSaveOptions).
            if (object.contains(key("number")))
                user.number =
                    m_r.string(object, path, key("number"),
                               QCoreApplication::translate("cambench::model", "user number"));
            user.allOutputs =
                m_r.boolean(object, path, key("allOutputs"),
                            QCoreApplication::translate("cambench::model", "\"all outputs\""));
            user.rights = quint32(m_r.integer(
                object, path, key("rights"),
                QCoreApplication::translate("cambench::model", "rights"), 0, 0xFFFFFFFFLL));
            user.outputAccess = QList<bool>(kUserAccessOutputs, false);
            const QJsonArray outputs = m_r.array(object, path, key("outputs"));
            for (int k = 0; k < outputs.size() && !m_r.failed(); ++k) {
                const int output = int(m_r.integerValue(
                    outputs.at(k), JsonReader::element(JsonReader::member(path, key("outputs")), k),
                    QCoreApplication::translate("cambench::model", "output"), 1,
                    kUserAccessOutputs));
                if (output >= 1) user.outputAccess[output - 1] = true;
            }
            users << user;
        }
        return users;
    }

    QDateTime readTime(const QJsonObject& object, const QString& path, const QString& name) {
        const QString text =
            m_r.string(object, path, name, QCoreApplication::translate("cambench::model", "time"));
        const QDateTime time = QDateTime::fromString(text, Qt::ISODateWithMs);
        if (!m_r.failed() && !time.isValid())
            m_r.fail(JsonReader::member(path, name),
                     QCoreApplication::translate("cambench::model", "\"%1\" is no ISO 8601 time")
                         .arg(text));
        return time.toUTC();
    }

    ProjectReadTimes readTimes(const QJsonObject& object) {
        ProjectReadTimes readAt;
        const QString path = key("readAt");
        for (const PartName& part : kPartNames) {
            if (object.contains(key(part.name)))
                readAt.parts.insert(part.part, readTime(object, path, key(part.name)));
        }
        const QJsonArray programs = object.value(key("programs")).toArray();
        for (int i = 0; i < programs.size() && !m_r.failed(); ++i) {
            const QString where = JsonReader::element(JsonReader::member(path, key("programs")), i);
            const QJsonObject entry = m_r.objectValue(programs.at(i), where);
            const int program = int(m_r.integer(
                entry, where, key("program"),
                QCoreApplication::translate("cambench::model", "program number"), 0, 32767));
            readAt.programs.insert(program, readTime(entry, where, key("time")));
        }
        return readAt;
    }

    JsonReader m_r;
};

}  // namespace

QStringList validateProject(const Project& project) {
    QStringList problems;
    const bool rotary = isRotaryAxis(project.settings);
    QSet<int> programNumbers;
    for (const CamProgram& program : project.programs) {
        if (programNumbers.contains(program.number))
            problems << QCoreApplication::translate("cambench::model", "Program %1 appears twice.")
                            .arg(program.number);
        programNumbers.insert(program.number);
        for (const CamProblem& problem : validateProgram(program, project.device, rotary))
            problems << problem.message + QLatin1Char('.');
        const QString name = nameProblem(program.name);
        if (!name.isEmpty())
            problems << QCoreApplication::translate("cambench::model", "Name of program %1: %2.")
                            .arg(program.number)
                            .arg(name);
        const auto named = project.names.programs.constFind(program.number);
        if (named != project.names.programs.cend() && *named != program.name) {
            problems << QCoreApplication::translate(
                            "cambench::model",
                            "Program %1 is named \"%2\", but the list of program "
                            "names says \"%3\".")
                            .arg(program.number)
                            .arg(program.name, *named);
        }
    }
    problems << validateDeadTimes(project.deadTimes, project.device);
    problems << validateDeadTimeModes(project.deadTimeModes, project.device);
    // One device word: a project cannot want two values for it.
    for (auto it = project.deadTimeModes.cbegin(); it != project.deadTimeModes.cend(); ++it) {
        if (project.deadTimes.contains(it.key()) &&
            project.deadTimes.value(it.key()) != it->normal) {
            problems << QCoreApplication::translate(
                            "cambench::model",
                            "Output %1: the dead time %2 and the dead time of its dead-time mode "
                            "%3 (0.1 ms) differ, but the device holds one value for both.")
                            .arg(it.key())
                            .arg(project.deadTimes.value(it.key()))
                            .arg(it->normal);
        }
    }
    for (const AnalogueCamTrack& track : project.analogueCams)
        problems << validateAnalogueCamTrack(track, project.device);
    if (project.programmingProgram)
        problems << validateProgrammingProgram(*project.programmingProgram, project.device);
    problems << validateNames(project.names, project.device);
    problems << validateSettings(project.settings);
    problems << validateUsers(project.users, UserNumbers::Optional);
    QSet<QPair<int, int>> networks;
    for (const PlcNetwork& network : project.plcNetworks) {
        problems << validatePlcNetwork(network);
        const QPair<int, int> id(network.area, network.number);
        if (networks.contains(id)) {
            problems << QCoreApplication::translate("cambench::model",
                                                    "PLC network %1 of area 0x%2 appears twice.")
                            .arg(network.number)
                            .arg(network.area, 2, 16, QLatin1Char('0'));
        }
        networks.insert(id);
    }
    return problems;
}

QByteArray projectToJson(const Project& project, const ProjectSaveOptions& options) {
    QJsonObject root = jsonFileHeader(kProjectFile);
    root.insert(key("device"), deviceInfoToJson(project.device));
    root.insert(key("readAt"), readTimesToJson(project.readAt));
    root.insert(key("settings"), settingsToJson(project.settings));
    QJsonArray programs;
    for (const CamProgram& program : project.programs) programs.append(programToJson(program));
    root.insert(key("programs"), programs);
    root.insert(key("deadTimes"), numberedToJson(project.deadTimes, "output", "deadTime"));
    root.insert(key("outputNames"), numberedToJson(project.names.outputs, "output", "name"));
    root.insert(key("programNames"), numberedToJson(project.names.programs, "program", "name"));
    QJsonArray users;
    for (const User& user : project.users)
        users.append(userToJson(user, options.includeUserNumbers));
    root.insert(key("users"), users);
    root.insert(key("plcNetworks"), plcNetworksToJson(project.plcNetworks));
    if (!project.deadTimeModes.isEmpty()) {
        QJsonArray modes;
        for (auto it = project.deadTimeModes.cbegin(); it != project.deadTimeModes.cend(); ++it) {
            modes.append(QJsonObject{{key("output"), it.key()},
                                     {key("mode"), deadTimeModeKey(it->mode)},
                                     {key("deadTime"), it->normal},
                                     {key("on"), it->on},
                                     {key("off"), it->off}});
        }
        root.insert(key("deadTimeModes"), modes);
    }
    if (!project.analogueCams.isEmpty())
        root.insert(key("analogueCams"), analogueCamsToJson(project.analogueCams));
    if (project.programmingProgram) {
        root.insert(key("programmingProgram"),
                    programmingProgramToJson(*project.programmingProgram));
    }
    if (project.eepromLock) root.insert(key("eepromLock"), *project.eepromLock);
    if (!project.minimumPulses.isEmpty())
        root.insert(key("minimumPulses"),
                    numberedToJson(project.minimumPulses, "output", "minimumPulse"));
    return toIndentedJson(root);
}

Result<Project> projectFromJson(const QByteArray& bytes) {
    const Result<QJsonObject> root = parseJsonFile(bytes, kProjectFile);
    if (!root) return root.error();
    return ProjectReader().read(*root);
}

Status saveProject(const QString& path, const Project& project, const ProjectSaveOptions& options) {
    return writeFileAtomically(path, projectToJson(project, options));
}

Result<Project> loadProject(const QString& path) {
    return loadFileWith<Project>(path, projectFromJson);
}

}  // namespace cambench
