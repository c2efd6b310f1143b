#include "device_reads.h"
#include "ui/camcon/camcon_jobs.h"

#include "incoming_values.h"
#include "ui/device_session.h"
#include "workspace.h"

#include "comm/camcon/usecases/program_read.h"
#include "comm/camcon/usecases/read_everything.h"

#include <QCoreApplication>
#include <QPointer>
#include <QWidget>

namespace cambench::devicereads {

namespace {

QDateTime now() {
    return QDateTime::currentDateTimeUtc();
}

// Puts a read into the workspace once it arrived; asks about edits then,
// not when the read started: edits made meanwhile count too.
Status take(QWidget* context, Workspace* workspace, const Project& incoming) {
    if (!takeIncoming(context, *workspace, incoming, ValueSource::Device))
        return Error{ErrorKind::Cancelled,
                     QCoreApplication::translate(
                         "cambench::DeviceReads",
                         "Not taken: your edits and the values shown are unchanged."),
                     0};
    return success();
}

template <class T>
quint64 readPart(QWidget* context, DeviceSession* session, Workspace* workspace,
                 const QString& title,
                 std::function<Result<T>(comm::CamConDevice&, comm::JobContext&)> work,
                 std::function<Project(const T&)> toProject, Done done) {
    QPointer<QWidget> parent(context);
    return runOnCamCon<T>(session, context, title, std::move(work),
                          [parent, workspace, toProject, done](Result<T> result) {
                              Status status =
                                  result ? take(parent, workspace, toProject(result.value()))
                                         : Status(result.error());
                              if (done) done(status);
                          });
}

}  // namespace

quint64 readIdentity(QWidget* context, DeviceSession* session, Workspace* workspace, Done done) {
    return readPart<DeviceInfo>(
        context, session, workspace,
        QCoreApplication::translate("cambench::DeviceReads", "Read device identity"),
        [](comm::CamConDevice& device, comm::JobContext&) { return device.readInfo(); },
        [](const DeviceInfo& read) {
            Project project;
            project.device = read;
            project.readAt.parts.insert(ProjectPart::Device, now());
            return project;
        },
        std::move(done));
}

quint64 readProgram(QWidget* context, DeviceSession* session, Workspace* workspace, int program,
                    Done done) {
    // The identity read when the device came on the line (the workspace
    // follows the connected device): no second identity read per program.
    const DeviceInfo device = workspace->info();
    return readPart<CamProgram>(
        context, session, workspace,
        QCoreApplication::translate("cambench::DeviceReads", "Read program %1").arg(program),
        [program, device](comm::CamConDevice& connection, comm::JobContext& job) {
            return usecases::readProgram(connection, device, program,
                                         usecases::UseCaseProgress::of(job));
        },
        [program](const CamProgram& read) {
            Project project;
            project.programs << read;
            project.readAt.programs.insert(program, now());
            return project;
        },
        std::move(done));
}

struct OutputSettings {
    QMap<int, QString> names;
    DeadTimes deadTimes;
};

quint64 readOutputSettings(QWidget* context, DeviceSession* session, Workspace* workspace,
                           Done done) {
    const int deadTimeOutputs = workspace->info().deadTimeOutputs;
    const int outputs = workspace->info().outputs;
    return readPart<OutputSettings>(
        context, session, workspace,
        QCoreApplication::translate("cambench::DeviceReads", "Read names and dead times"),
        [deadTimeOutputs, outputs](comm::CamConDevice& device,
                                   comm::JobContext& job) -> Result<OutputSettings> {
            OutputSettings settings;
            auto deadTimes = device.readDeadTimes(deadTimeOutputs);
            if (!deadTimes) return deadTimes.error();
            settings.deadTimes = deadTimes.value();
            if (!device.has(comm::CamConCapability::OutputNames)) return settings;
            for (int output = 1; output <= outputs; ++output) {
                if (job.cancelled()) return Error::cancelled();
                job.progress(output, outputs);
                auto name = device.readOutputName(output);
                if (!name) return name.error();
                settings.names.insert(output, name.value());
            }
            return settings;
        },
        [](const OutputSettings& read) {
            Project project;
            project.names.outputs = read.names;
            project.deadTimes = read.deadTimes;
            project.readAt.parts.insert(ProjectPart::DeadTimes, now());
            project.readAt.parts.insert(ProjectPart::OutputNames, now());
            return project;
        },
        std::move(done));
}

quint64 readSettings(QWidget* context, DeviceSession* session, Workspace* workspace, Done done) {
    return readPart<SystemSettings>(
        context, session, workspace,
        QCoreApplication::translate("cambench::DeviceReads", "Read settings"),
        [](comm::CamConDevice& device, comm::JobContext&) { return device.readSettings(); },
        [](const SystemSettings& read) {
            Project project;
            project.settings = read;
            project.readAt.parts.insert(ProjectPart::Settings, now());
            return project;
        },
        std::move(done));
}

quint64 readUsers(QWidget* context, DeviceSession* session, Workspace* workspace, Done done) {
    return readPart<QList<User>>(
        context, session, workspace,
        QCoreApplication::translate("cambench::DeviceReads", "Read users"),
        [](comm::CamConDevice& device, comm::JobContext&) -> Result<QList<User>> {
            if (!device.has(comm::CamConCapability::Users))
                return device.missing(comm::CamConCapability::Users);
            return device.readUsers();
        },
        [](const QList<User>& read) {
            Project project;
            project.users = read;
            project.readAt.parts.insert(ProjectPart::Users, now());
            return project;
        },
        std::move(done));
}

quint64 readPlcNetwork(QWidget* context, DeviceSession* session, Workspace* workspace, int area,
                       int number, Done done) {
    return readPart<PlcNetwork>(
        context, session, workspace,
        QCoreApplication::translate("cambench::DeviceReads", "Read PLC network"),
        [area, number](comm::CamConDevice& device, comm::JobContext&) {
            return device.readPlcNetwork(area, number);
        },
        [](const PlcNetwork& read) {
            Project project;
            project.plcNetworks << read;
            // One network, not the whole part: no read time for the part.
            project.readAt.parts.insert(ProjectPart::PlcNetworks, {});
            return project;
        },
        std::move(done));
}

quint64 readEverything(QWidget* context, DeviceSession* session, Workspace* workspace,
                       EverythingDone done) {
    QPointer<QWidget> parent(context);
    return runOnCamCon<usecases::ReadEverything>(
        session, context, QCoreApplication::translate("cambench::DeviceReads", "Read everything"),
        [](comm::CamConDevice& device, comm::JobContext& job) -> Result<usecases::ReadEverything> {
            const Result<DeviceInfo> identity = device.readInfo();
            if (!identity) return identity.error();
            return usecases::readEverything(device, identity.value(),
                                            usecases::UseCaseProgress::of(job));
        },
        [parent, workspace, done](Result<usecases::ReadEverything> result) {
            const Status status =
                result ? take(parent, workspace, result->project) : Status(result.error());
            if (done) done(status, result ? result->skipped : QStringList());
        });
}

}  // namespace cambench::devicereads
