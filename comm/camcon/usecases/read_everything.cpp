#include "read_everything.h"
#include "program_read.h"

#include "model/camcon/data_validation.h"
#include "model/camcon/system_settings.h"

#include <QCoreApplication>
#include <QDateTime>

namespace cambench::usecases {

namespace {

// "?GTXT1 (key1, key2)", a page the device does not know, as the labels a
// person sees on the Settings page ("Encoder text 1, Encoder text 2").
QString settingLabels(const QString& page) {
    const qsizetype open = page.indexOf(QLatin1Char('('));
    const qsizetype close = page.lastIndexOf(QLatin1Char(')'));
    if (open < 0 || close < open) return page;
    QStringList labels;
    for (const QString& key : page.mid(open + 1, close - open - 1).split(QStringLiteral(", "))) {
        const SettingSpec* spec = findSetting(key.trimmed());
        labels << (spec && *spec->label ? QCoreApplication::translate("Settings", spec->label)
                                        : key.trimmed());
    }
    return labels.join(QStringLiteral(", "));
}

using comm::CamConCapability;
using comm::CamConDevice;

// PLC areas with the setting that says how many networks each has.
struct PlcArea {
    int area;
    const char* countKey;
};
const PlcArea kPlcAreas[] = {
    {PlcNetwork::O, "plcOutputs"},
    {PlcNetwork::P, "inputCount"},
    {PlcNetwork::M, "plcFlags"},
    {PlcNetwork::X, "plcXFlags"},
};

QDateTime now() {
    return QDateTime::currentDateTimeUtc();
}

// Reads the parts in turn, counting steps on one bar.
class Reader {
public:
    Reader(CamConDevice& connection, const DeviceInfo& device, const UseCaseProgress& progress)
        : m_connection(connection), m_device(device), m_progress(progress) {}

    Result<ReadEverything> run() {
        Project& project = m_result.project;
        project.device = m_device;
        project.readAt.parts.insert(ProjectPart::Device, now());
        // Settings first: they say how many PLC networks there are.
        if (const Status ok = readSettings(); !ok) return ok.error();
        const QMap<int, int> plcCounts = m_connection.has(CamConCapability::PlcNetworks)
                                             ? plcNetworkCounts(project.settings)
                                             : QMap<int, int>();
        qint64 plcTotal = 0;
        for (const int count : plcCounts) plcTotal += count;
        const bool names = m_connection.has(CamConCapability::OutputNames);
        m_total = 1 + qint64(m_device.programs) * m_device.outputs + m_device.deadTimeOutputs +
                  (names ? m_device.outputs : 0) + 1 + plcTotal + 1 + 1 + kAnalogueOutputs + 1;
        m_done = 1;
        // Before the programs: reading cams over the table interface selects
        // their program as the programming program.
        if (const Status ok = readProgrammingProgram(); !ok) return ok.error();
        for (int program = 0; program < m_device.programs; ++program) {
            if (const Status ok = readProgram(program); !ok) return ok.error();
        }
        if (const Status ok = restoreProgrammingProgram(); !ok) return ok.error();
        if (const Status ok = readDeadTimes(); !ok) return ok.error();
        if (const Status ok = readDeadTimeModes(); !ok) return ok.error();
        if (const Status ok = readAnalogueCams(); !ok) return ok.error();
        if (const Status ok = readEepromLock(); !ok) return ok.error();
        if (const Status ok = readOutputNames(names); !ok) return ok.error();
        if (const Status ok = readUsers(); !ok) return ok.error();
        if (const Status ok = readPlcNetworks(plcCounts); !ok) return ok.error();
        m_progress.report(m_total, m_total,
                          QCoreApplication::translate("cambench::usecases", "read everything"));
        return m_result;
    }

private:
    Status step(qint64 steps, const QString& text) {
        if (m_progress.cancelled()) return Error::cancelled();
        m_progress.report(m_done, m_total, text);
        m_done += steps;
        return success();
    }

    Status readSettings() {
        m_progress.report(
            0, 1, QCoreApplication::translate("cambench::usecases", "reading the settings"));
        QStringList unknown;
        Result<SystemSettings> settings = m_connection.readSettings(&unknown);
        if (!settings) return settings.error();
        m_result.project.settings = *settings;
        m_result.project.readAt.parts.insert(ProjectPart::Settings, now());
        for (const QString& page : unknown) {
            m_result.skipped << QCoreApplication::translate(
                                    "cambench::usecases",
                                    "Settings the device does not know, not read: %1.")
                                    .arg(settingLabels(page));
        }
        return success();
    }

    Status readProgram(int program) {
        if (m_progress.cancelled()) return Error::cancelled();
        const UseCaseProgress part = m_progress.slice(m_done, m_device.outputs, m_total);
        Result<CamProgram> read = usecases::readProgram(m_connection, m_device, program, part);
        if (!read) return read.error();
        m_done += m_device.outputs;
        m_result.project.programs << *read;
        m_result.project.readAt.programs.insert(program, now());
        return success();
    }

    Status readDeadTimes() {
        if (const Status ok =
                step(m_device.deadTimeOutputs,
                     QCoreApplication::translate("cambench::usecases", "reading dead times"));
            !ok)
            return ok;
        Result<DeadTimes> deadTimes = m_connection.readDeadTimes(m_device.deadTimeOutputs);
        if (!deadTimes) return deadTimes.error();
        m_result.project.deadTimes = *deadTimes;
        m_result.project.readAt.parts.insert(ProjectPart::DeadTimes, now());
        return success();
    }

    // Table interface only: a project read there carries them to another
    // device (issue 12, point 2).
    Status readDeadTimeModes() {
        if (const Status ok = step(
                1, QCoreApplication::translate("cambench::usecases", "reading dead-time modes"));
            !ok)
            return ok;
        // The ASCII protocol has only the plain dead time of every output
        // (read above); no note, as on every ASCII read it would say the same.
        if (!m_connection.has(CamConCapability::DeadTimeModes)) return success();
        Result<DeadTimeModes> modes = m_connection.readDeadTimeModes(m_device.deadTimeOutputs);
        if (!modes) return modes.error();
        m_result.project.deadTimeModes = *modes;
        m_result.project.readAt.parts.insert(ProjectPart::DeadTimeModes, now());
        return success();
    }

    // The table interface's other sections: absent elsewhere, never carried over.
    Status readProgrammingProgram() {
        if (const Status ok = step(1, QCoreApplication::translate(
                                          "cambench::usecases", "reading the programming program"));
            !ok)
            return ok;
        if (!m_connection.has(CamConCapability::ProgrammingProgram)) return success();
        Result<ProgrammingProgram> programming = m_connection.readProgrammingProgram();
        if (!programming) return programming.error();
        m_result.project.programmingProgram = *programming;
        m_result.project.readAt.parts.insert(ProjectPart::ProgrammingProgram, now());
        return success();
    }

    // A read leaves the device as it found it: the programming program the
    // cam reads selected is set back to the one read before them (a PLC
    // may edit that program).
    Status restoreProgrammingProgram() {
        const std::optional<ProgrammingProgram>& before = m_result.project.programmingProgram;
        if (!before) return success();
        Result<ProgrammingProgram> current = m_connection.readProgrammingProgram();
        if (!current) return current.error();
        if (*current == *before) return success();
        const Status restored = m_connection.writeProgrammingProgram(*before);
        if (!restored) {
            Error error = restored.error();
            error.message = QCoreApplication::translate(
                                "cambench::usecases",
                                "Reading the programs selected program %1 as the programming "
                                "program; setting it back to program %2 failed: %3")
                                .arg(current->program)
                                .arg(before->program)
                                .arg(error.message);
            return error;
        }
        return success();
    }

    // Only the analogue outputs the device says it has: one without any
    // refuses their areas, which must not end the whole read.
    Status readAnalogueCams() {
        const bool reachable = m_connection.has(CamConCapability::AnalogueCams);
        int count = 0;
        if (reachable) {
            const Result<int> read = m_connection.readAnalogueOutputCount();
            if (!read) return read.error();
            count = *read;
            if (count == 0) {
                m_result.skipped << QCoreApplication::translate(
                    "cambench::usecases",
                    "Analogue cams: this device has no analogue outputs, so it has no "
                    "analogue cams.");
            }
        }
        for (int output = 1; output <= kAnalogueOutputs; ++output) {
            if (const Status ok = step(1, QCoreApplication::translate("cambench::usecases",
                                                                      "reading analogue output %1")
                                              .arg(output));
                !ok)
                return ok;
            if (output > count) continue;
            Result<AnalogueCamTrack> track = m_connection.readAnalogueCams(output);
            if (!track) return track.error();
            m_result.project.analogueCams << *track;
        }
        if (reachable) m_result.project.readAt.parts.insert(ProjectPart::AnalogueCams, now());
        return success();
    }

    Status readEepromLock() {
        if (const Status ok = step(
                1, QCoreApplication::translate("cambench::usecases", "reading the EEPROM lock"));
            !ok)
            return ok;
        if (!m_connection.has(CamConCapability::EepromLock)) return success();
        Result<bool> locked = m_connection.readEepromLock();
        if (!locked) return locked.error();
        m_result.project.eepromLock = *locked;
        m_result.project.readAt.parts.insert(ProjectPart::EepromLock, now());
        return success();
    }

    Status readOutputNames(bool reachable) {
        if (!reachable) {
            skip(QCoreApplication::translate("cambench::usecases", "Output names"),
                 CamConCapability::OutputNames);
            return success();
        }
        QMap<int, QString> names;
        for (int output = 1; output <= m_device.outputs; ++output) {
            if (const Status ok = step(
                    1, QCoreApplication::translate("cambench::usecases", "reading output names"));
                !ok)
                return ok;
            const Result<QString> name = m_connection.readOutputName(output);
            if (!name && name.error().kind == ErrorKind::NotUnderstood) {
                m_result.skipped << QCoreApplication::translate("cambench::usecases",
                                                                "Output names: %1")
                                        .arg(name.error().message);
                return success();
            }
            if (!name) return name.error();
            if (!name->isEmpty()) names.insert(output, *name);
        }
        m_result.project.names.outputs = names;
        m_result.project.readAt.parts.insert(ProjectPart::OutputNames, now());
        return success();
    }

    Status readUsers() {
        if (const Status ok =
                step(1, QCoreApplication::translate("cambench::usecases", "reading users"));
            !ok)
            return ok;
        if (!m_connection.has(CamConCapability::Users)) {
            skip(QCoreApplication::translate("cambench::usecases", "Users"),
                 CamConCapability::Users);
            return success();
        }
        Result<QList<User>> users = m_connection.readUsers();
        if (!users) return users.error();
        m_result.project.users = *users;
        m_result.project.readAt.parts.insert(ProjectPart::Users, now());
        return success();
    }

    Status readPlcNetworks(const QMap<int, int>& counts) {
        if (!m_connection.has(CamConCapability::PlcNetworks)) {
            skip(QCoreApplication::translate("cambench::usecases", "PLC networks"),
                 CamConCapability::PlcNetworks);
            return success();
        }
        QList<PlcNetwork> networks;
        for (auto it = counts.cbegin(); it != counts.cend(); ++it) {
            for (int number = 0; number < *it; ++number) {
                if (const Status ok = step(1, QCoreApplication::translate("cambench::usecases",
                                                                          "reading PLC networks"));
                    !ok)
                    return ok;
                const Result<PlcNetwork> network = m_connection.readPlcNetwork(it.key(), number);
                if (!network) return network.error();
                // Empty networks are the default: the project lists the used ones.
                if (!network->isEmpty()) networks << *network;
            }
        }
        m_result.project.plcNetworks = networks;
        m_result.project.readAt.parts.insert(ProjectPart::PlcNetworks, now());
        return success();
    }

    void skip(const QString& part, CamConCapability capability) {
        m_result.skipped << QStringLiteral("%1: %2").arg(part, m_connection.lacks(capability));
    }

    CamConDevice& m_connection;
    const DeviceInfo& m_device;
    const UseCaseProgress& m_progress;
    ReadEverything m_result;
    qint64 m_done = 0;
    qint64 m_total = 1;
};

}  // namespace

Result<ReadEverything> readEverything(CamConDevice& connection, const DeviceInfo& device,
                                      const UseCaseProgress& progress) {
    return Reader(connection, device, progress).run();
}

QMap<int, int> plcNetworkCounts(const SystemSettings& settings) {
    QMap<int, int> counts;
    for (const PlcArea& area : kPlcAreas) {
        const QString key = QLatin1String(area.countKey);
        if (!settings.contains(key)) continue;
        counts.insert(area.area, int(qBound(qint64(0), settings.value(key).toLongLong(),
                                            qint64(kMaxPlcNumber + 1))));
    }
    return counts;
}

}  // namespace cambench::usecases
