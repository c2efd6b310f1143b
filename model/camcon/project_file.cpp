#include "project_file.h"

#include "model/atomic_file.h"
#include "cam_validation.h"
#include "data_validation.h"
#include "device_info_json.h"
#include "model/file_read.h"
#include "model/json_file.h"
#include "model/json_reader.h"

#include <QJsonArray>
#include <QSet>

namespace cambench {

namespace {

const JsonFileType kProjectFile{"cambench-project", kProjectFormatVersion, "project"};

// Outputs the user access table can address (32 bytes of bits).
constexpr int kUserAccessOutputs = 256;

QString key(const char* text) {
    return QString::fromLatin1(text);
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

QJsonObject settingsToJson(const SystemSettings& settings) {
    QJsonObject object;
    for (auto it = settings.cbegin(); it != settings.cend(); ++it) {
        const SettingSpec* spec = findSetting(it.key());
        if (spec && spec->kind == SettingKind::Text)
            object.insert(it.key(), it->toString());
        else
            object.insert(it.key(), it->toLongLong());
    }
    return object;
}

template <class Map>
QJsonArray numberedToJson(const Map& map, const char* numberKey, const char* valueKey) {
    QJsonArray array;
    for (auto it = map.cbegin(); it != map.cend(); ++it)
        array.append(QJsonObject{{key(numberKey), it.key()}, {key(valueKey), *it}});
    return array;
}

QJsonObject userToJson(const User& user) {
    QJsonArray outputs;
    for (int i = 0; i < user.outputAccess.size(); ++i) {
        if (user.outputAccess.at(i)) outputs.append(i + 1);
    }
    return {{key("name"), user.name},
            {key("number"), user.number},
            {key("allOutputs"), user.allOutputs},
            {key("rights"), qint64(user.rights)},
            {key("outputs"), outputs}};
}

QJsonObject plcNetworkToJson(const PlcNetwork& network) {
    QJsonArray symbols;
    for (quint16 symbol : network.symbols) symbols.append(symbol);
    return {{key("area"), network.area},
            {key("number"), network.number},
            {key("value"), network.value},
            {key("reset"), network.reset},
            {key("symbols"), symbols}};
}

// ---- reading ----

// Reads the top-level sections in an order that lets later ones be checked
// against earlier ones (cams against the device and the axis type).
class ProjectReader {
public:
    Result<Project> read(const QJsonObject& root) {
        Project project;
        project.device = readDeviceInfo(m_r, m_r.object(root, {}, key("device")), key("device"));
        project.settings = readSettings(m_r.object(root, {}, key("settings")));
        const bool rotary = isRotaryAxis(project.settings);
        project.programs =
            readPrograms(m_r.array(root, {}, key("programs")), project.device, rotary);
        project.deadTimes = readDeadTimes(m_r.array(root, {}, key("deadTimes")), project.device);
        project.names.outputs = readNames(m_r.array(root, {}, key("outputNames")), "outputNames",
                                          "output", 1, project.device.outputs);
        project.names.programs = readNames(m_r.array(root, {}, key("programNames")), "programNames",
                                           "program", 0, project.device.programs - 1);
        project.users = readUsers(m_r.array(root, {}, key("users")));
        project.plcNetworks = readPlcNetworks(m_r.array(root, {}, key("plcNetworks")));
        if (m_r.failed()) return Error::invalidData(m_r.problem() + QLatin1Char('.'));
        // Whatever the per-value checks above cannot see (e.g. a program
        // name that disagrees with programNames).
        const QStringList problems = validateProject(project);
        if (!problems.isEmpty()) return Error::invalidData(problems.first());
        return project;
    }

private:
    SystemSettings readSettings(const QJsonObject& object) {
        SystemSettings settings;
        for (auto it = object.constBegin(); it != object.constEnd() && !m_r.failed(); ++it) {
            const QString path = JsonReader::member(key("settings"), it.key());
            const SettingSpec* spec = findSetting(it.key());
            if (!spec) {
                m_r.fail(path, QStringLiteral("there is no such setting"));
                break;
            }
            QVariant value;
            if (spec->kind == SettingKind::Text) {
                if (!it->isString()) {
                    m_r.fail(path, QStringLiteral("the value is not a string"));
                    break;
                }
                value = it->toString();
            } else {
                value = m_r.integerValue(*it, path, QStringLiteral("the value"),
                                         std::numeric_limits<qint64>::min(),
                                         std::numeric_limits<qint64>::max());
            }
            const QString problem = settingValueProblem(*spec, value);
            if (!problem.isEmpty()) m_r.fail(path, problem);
            settings.insert(it.key(), value);
        }
        return settings;
    }

    QList<CamProgram> readPrograms(const QJsonArray& array, const DeviceInfo& device, bool rotary) {
        QList<CamProgram> programs;
        QSet<int> seen;
        for (int i = 0; i < array.size() && !m_r.failed(); ++i) {
            const QString path = JsonReader::element(key("programs"), i);
            const QJsonObject object = m_r.objectValue(array.at(i), path);
            CamProgram program;
            program.number =
                int(m_r.integer(object, path, key("number"), QStringLiteral("program number"), 0,
                                device.programs - 1));
            program.name = m_r.string(object, path, key("name"), QStringLiteral("program name"));
            if (!m_r.failed() && seen.contains(program.number)) {
                m_r.fail(JsonReader::member(path, key("number")),
                         QStringLiteral("program %1 appears twice").arg(program.number));
            }
            seen.insert(program.number);
            checkName(program.name, JsonReader::member(path, key("name")));
            const QJsonArray tracks = m_r.array(object, path, key("tracks"));
            for (int j = 0; j < tracks.size() && !m_r.failed(); ++j) {
                const QString trackPath =
                    JsonReader::element(JsonReader::member(path, key("tracks")), j);
                const Track track = readTrack(tracks.at(j), trackPath, device);
                if (!m_r.failed() && program.tracks.contains(track.output)) {
                    m_r.fail(JsonReader::member(trackPath, key("output")),
                             QStringLiteral("output %1 appears twice").arg(track.output));
                }
                checkTrack(track, program.number, device, rotary, trackPath);
                program.tracks.insert(track.output, track);
            }
            programs << program;
        }
        return programs;
    }

    Track readTrack(const QJsonValue& value, const QString& path, const DeviceInfo& device) {
        const QJsonObject object = m_r.objectValue(value, path);
        Track track;
        track.output = int(
            m_r.integer(object, path, key("output"), QStringLiteral("output"), 1, device.outputs));
        const QJsonArray cams = m_r.array(object, path, key("cams"));
        const QString camsPath = JsonReader::member(path, key("cams"));
        for (int k = 0; k < cams.size() && !m_r.failed(); ++k) {
            const QString camPath = JsonReader::element(camsPath, k);
            const QJsonArray pair = m_r.arrayValue(cams.at(k), camPath);
            if (!m_r.failed() && pair.size() != 2) {
                m_r.fail(camPath, QStringLiteral("a cam is a pair [switch-on point, "
                                                 "switch-off point], this has %1 values")
                                      .arg(pair.size()));
            }
            Cam cam;
            cam.on =
                qint32(m_r.integerValue(pair.at(0), camPath, QStringLiteral("switch-on point")));
            cam.off =
                qint32(m_r.integerValue(pair.at(1), camPath, QStringLiteral("switch-off point")));
            track.cams << cam;
        }
        return track;
    }

    void checkTrack(const Track& track, int program, const DeviceInfo& device, bool rotary,
                    const QString& path) {
        if (m_r.failed()) return;
        const QList<CamProblem> problems = validateTrack(track, program, device, rotary);
        if (problems.isEmpty()) return;
        const CamProblem& first = problems.first();
        m_r.fail(first.cam >= 0
                     ? JsonReader::element(JsonReader::member(path, key("cams")), first.cam)
                     : path,
                 first.message);
    }

    void checkName(const QString& name, const QString& path) {
        if (m_r.failed()) return;
        const QString problem = nameProblem(name);
        if (!problem.isEmpty()) m_r.fail(path, problem);
    }

    DeadTimes readDeadTimes(const QJsonArray& array, const DeviceInfo& device) {
        DeadTimes deadTimes;
        for (int i = 0; i < array.size() && !m_r.failed(); ++i) {
            const QString path = JsonReader::element(key("deadTimes"), i);
            const QJsonObject object = m_r.objectValue(array.at(i), path);
            const int output = int(m_r.integer(
                object, path, key("output"), QStringLiteral("output"), 1, device.deadTimeOutputs));
            const qint32 value = qint32(m_r.integer(
                object, path, key("deadTime"), QStringLiteral("dead time"), 0, device.maxDeadTime));
            if (!m_r.failed() && deadTimes.contains(output)) {
                m_r.fail(JsonReader::member(path, key("output")),
                         QStringLiteral("output %1 appears twice").arg(output));
            }
            deadTimes.insert(output, value);
        }
        return deadTimes;
    }

    QMap<int, QString> readNames(const QJsonArray& array, const char* section,
                                 const char* numberKey, int min, int max) {
        QMap<int, QString> names;
        for (int i = 0; i < array.size() && !m_r.failed(); ++i) {
            const QString path = JsonReader::element(key(section), i);
            const QJsonObject object = m_r.objectValue(array.at(i), path);
            const int number =
                int(m_r.integer(object, path, key(numberKey), key(numberKey), min, max));
            const QString name = m_r.string(object, path, key("name"), QStringLiteral("name"));
            checkName(name, JsonReader::member(path, key("name")));
            if (!m_r.failed() && names.contains(number)) {
                m_r.fail(JsonReader::member(path, key(numberKey)),
                         QStringLiteral("%1 %2 appears twice").arg(key(numberKey)).arg(number));
            }
            names.insert(number, name);
        }
        return names;
    }

    QList<User> readUsers(const QJsonArray& array) {
        QList<User> users;
        QHash<QString, int> numbers;
        for (int i = 0; i < array.size() && !m_r.failed(); ++i) {
            const QString path = JsonReader::element(key("users"), i);
            const QJsonObject object = m_r.objectValue(array.at(i), path);
            User user;
            user.name = m_r.string(object, path, key("name"), QStringLiteral("user name"));
            user.number = m_r.string(object, path, key("number"), QStringLiteral("user number"));
            user.allOutputs =
                m_r.boolean(object, path, key("allOutputs"), QStringLiteral("\"all outputs\""));
            user.rights = quint32(m_r.integer(object, path, key("rights"), QStringLiteral("rights"),
                                              0, 0xFFFFFFFFLL));
            user.outputAccess = QList<bool>(kUserAccessOutputs, false);
            const QJsonArray outputs = m_r.array(object, path, key("outputs"));
            for (int k = 0; k < outputs.size() && !m_r.failed(); ++k) {
                const int output = int(m_r.integerValue(
                    outputs.at(k), JsonReader::element(JsonReader::member(path, key("outputs")), k),
                    QStringLiteral("output"), 1, kUserAccessOutputs));
                if (output >= 1) user.outputAccess[output - 1] = true;
            }
            if (m_r.failed()) break;
            const QString problem = userProblem(user);
            if (!problem.isEmpty())
                m_r.fail(path, problem);
            else if (numbers.contains(user.number))
                m_r.fail(path, QStringLiteral("the user number is the same as that of users[%1]")
                                   .arg(numbers.value(user.number)));
            numbers.insert(user.number, i);
            users << user;
        }
        return users;
    }

    QList<PlcNetwork> readPlcNetworks(const QJsonArray& array) {
        QList<PlcNetwork> networks;
        QSet<QPair<int, int>> seen;
        for (int i = 0; i < array.size() && !m_r.failed(); ++i) {
            const QString path = JsonReader::element(key("plcNetworks"), i);
            const QJsonObject object = m_r.objectValue(array.at(i), path);
            PlcNetwork network;
            network.area = int(m_r.integer(object, path, key("area"), QStringLiteral("area"),
                                           PlcNetwork::O, PlcNetwork::X));
            network.number = int(m_r.integer(object, path, key("number"),
                                             QStringLiteral("network number"), 0, kMaxPlcNumber));
            network.value =
                qint32(m_r.integer(object, path, key("value"), QStringLiteral("value")));
            network.reset = quint16(
                m_r.integer(object, path, key("reset"), QStringLiteral("reset field"), 0, 0xFFFF));
            const QJsonArray symbols = m_r.array(object, path, key("symbols"));
            const QString symbolsPath = JsonReader::member(path, key("symbols"));
            if (!m_r.failed() && symbols.size() != PlcNetwork::kSymbols) {
                m_r.fail(symbolsPath, QStringLiteral("%1 symbols, expected %2 (%3 paths of %4)")
                                          .arg(symbols.size())
                                          .arg(PlcNetwork::kSymbols)
                                          .arg(PlcNetwork::kPaths)
                                          .arg(PlcNetwork::kSymbolsPerPath));
            }
            for (int k = 0; k < PlcNetwork::kSymbols && !m_r.failed(); ++k) {
                network.symbols[std::size_t(k)] =
                    quint16(m_r.integerValue(symbols.at(k), JsonReader::element(symbolsPath, k),
                                             QStringLiteral("symbol"), 0, 0xFFFF));
            }
            const QPair<int, int> id(network.area, network.number);
            if (!m_r.failed() && seen.contains(id))
                m_r.fail(path, QStringLiteral("this network appears twice"));
            seen.insert(id);
            networks << network;
        }
        return networks;
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
            problems << QStringLiteral("Program %1 appears twice.").arg(program.number);
        programNumbers.insert(program.number);
        for (const CamProblem& problem : validateProgram(program, project.device, rotary))
            problems << problem.message + QLatin1Char('.');
        const QString name = nameProblem(program.name);
        if (!name.isEmpty())
            problems << QStringLiteral("Name of program %1: %2.").arg(program.number).arg(name);
        const auto named = project.names.programs.constFind(program.number);
        if (named != project.names.programs.cend() && *named != program.name) {
            problems << QStringLiteral(
                            "Program %1 is named \"%2\", but the list of program "
                            "names says \"%3\".")
                            .arg(program.number)
                            .arg(program.name, *named);
        }
    }
    problems << validateDeadTimes(project.deadTimes, project.device);
    problems << validateNames(project.names, project.device);
    problems << validateSettings(project.settings);
    problems << validateUsers(project.users);
    QSet<QPair<int, int>> networks;
    for (const PlcNetwork& network : project.plcNetworks) {
        problems << validatePlcNetwork(network);
        const QPair<int, int> id(network.area, network.number);
        if (networks.contains(id)) {
            problems << QStringLiteral("PLC network %1 of area 0x%2 appears twice.")
                            .arg(network.number)
                            .arg(network.area, 2, 16, QLatin1Char('0'));
        }
        networks.insert(id);
    }
    return problems;
}

QByteArray projectToJson(const Project& project, const ProjectSaveOptions&) {
    QJsonObject root = jsonFileHeader(kProjectFile);
    root.insert(key("device"), deviceInfoToJson(project.device));
    root.insert(key("settings"), settingsToJson(project.settings));
    QJsonArray programs;
    for (const CamProgram& program : project.programs) programs.append(programToJson(program));
    root.insert(key("programs"), programs);
    root.insert(key("deadTimes"), numberedToJson(project.deadTimes, "output", "deadTime"));
    root.insert(key("outputNames"), numberedToJson(project.names.outputs, "output", "name"));
    root.insert(key("programNames"), numberedToJson(project.names.programs, "program", "name"));
    QJsonArray users;
    for (const User& user : project.users) users.append(userToJson(user));
    root.insert(key("users"), users);
    QJsonArray networks;
    for (const PlcNetwork& network : project.plcNetworks)
        networks.append(plcNetworkToJson(network));
    root.insert(key("plcNetworks"), networks);
    return toIndentedJson(root);
}

Result<Project> projectFromJson(const QByteArray& bytes) {
    const Result<QJsonObject> root = parseJsonFile(bytes, kProjectFile);
    if (!root) return root.error();
    return ProjectReader().read(*root);
}

Status saveProject(const QString& path, const Project& project, const ProjectSaveOptions& options) {
    const QStringList problems = validateProject(project);
    if (!problems.isEmpty()) {
        QString message = QStringLiteral("%1 was not saved: %2").arg(path, problems.first());
        if (problems.size() > 1)
            message += QStringLiteral(" (and %1 more problems)").arg(problems.size() - 1);
        return Error::invalidData(message);
    }
    return writeFileAtomically(path, projectToJson(project, options));
}

Result<Project> loadProject(const QString& path) {
    const Result<QByteArray> bytes = readFileBytes(path);
    if (!bytes) return bytes.error();
    Result<Project> project = projectFromJson(*bytes);
    if (!project) return inFile(path, project.error());
    return project;
}

}  // namespace cambench
