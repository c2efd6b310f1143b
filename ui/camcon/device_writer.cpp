#include "device_writer.h"
#include "ui/camcon/camcon_jobs.h"
#include "ui/camcon/link_settings_question.h"

#include "ui/last_write_report.h"

#include "ui/device_session.h"
#include "ui/report_dialog.h"
#include "workspace.h"

#include "comm/camcon/usecases/value_text.h"
#include "comm/camcon/usecases/write_items.h"
#include "ui/camcon/cameditor/cam_document.h"

#include <QCoreApplication>
#include <QHash>
#include <QSet>
#include <QWidget>

namespace cambench {

namespace {

QString otherDeviceRefusal(const DeviceInfo& copiesFrom, const DeviceInfo& now) {
    return QCoreApplication::translate(
               "cambench::DeviceWriter",
               "Nothing was written: the device on the line (CamCon %1, device number %2, %3 "
               "cams programmed) is not the one the values shown as on the device were read "
               "from (CamCon %4, device number %5, %6 cams programmed).\nRead the device again "
               "or use Compare with device; your edits are kept.")
        .arg(now.epromDate)
        .arg(now.deviceNumber)
        .arg(now.programmedCams)
        .arg(copiesFrom.epromDate)
        .arg(copiesFrom.deviceNumber)
        .arg(copiesFrom.programmedCams);
}

bool knownAfter(usecases::WriteState state) {
    return state != usecases::WriteState::Unknown && state != usecases::WriteState::NotSent;
}

// The outcome of an item of the plan the report says nothing of.
template <class T>
usecases::ItemOutcome<T> notSent(const QString& label) {
    usecases::ItemOutcome<T> missing;
    missing.label = label;
    missing.state = usecases::WriteState::NotSent;
    missing.error = Error{ErrorKind::InvalidData,
                          QCoreApplication::translate(
                              "cambench::DeviceWriter",
                              "The write's report says nothing of this item: it counts as not "
                              "written. Read the device to see what it holds."),
                          0};
    return missing;
}

// One list of a report's outcomes, found by the key of their item. An item
// of the plan the report says nothing of is added to the report as not
// sent: nothing applies it, and the report never counts it as done.
template <class T>
class OutcomesByItem {
public:
    explicit OutcomesByItem(QList<usecases::KeyedOutcome<T>>& outcomes) : m_outcomes(outcomes) {
        for (qsizetype i = 0; i < outcomes.size(); ++i) m_index.insert(outcomes.at(i).item, i);
    }

    usecases::KeyedOutcome<T> of(const WorkspaceItem& item, const QString& label) {
        if (const auto it = m_index.constFind(item); it != m_index.cend())
            return m_outcomes.at(*it);
        const usecases::KeyedOutcome<T> missing = usecases::keyed(item, notSent<T>(label));
        m_index.insert(item, m_outcomes.size());
        m_outcomes.append(missing);
        return missing;
    }

private:
    QList<usecases::KeyedOutcome<T>>& m_outcomes;
    QHash<WorkspaceItem, qsizetype> m_index;
};

void applyTracks(CamDocument& cams, const usecases::WritePlan& plan,
                 usecases::WriteReport& report) {
    // Programs never read are written whole; their device copy is known
    // afterwards only when every one of their items is.
    QMap<int, CamProgram> assembled;
    QSet<int> incomplete;
    OutcomesByItem<QString> names(report.programNames);
    for (const usecases::NameWrite& write : plan.programNames) {
        const int program = write.number;
        const auto outcome =
            names.of(usecases::programNameItem(write), usecases::programNameLabel(program));
        if (cams.hasDeviceCopy(program)) {
            if (outcome.actual) cams.setDeviceProgramName(program, *outcome.actual);
        } else if (outcome.actual) {
            assembled[program].number = program;
            assembled[program].name = *outcome.actual;
        } else {
            incomplete.insert(program);
        }
    }
    OutcomesByItem<Track> tracks(report.tracks);
    for (const usecases::TrackWrite& write : plan.tracks) {
        const int program = write.program;
        const auto outcome =
            tracks.of(usecases::itemOf(write), usecases::trackLabel(program, write.wanted.output));
        if (cams.hasDeviceCopy(program)) {
            if (outcome.actual) {
                cams.setDeviceTrack(program, *outcome.actual);
            } else if (!knownAfter(outcome.state)) {
                // What the device holds on this output is not known any
                // more: say so there; the other outputs keep what the report
                // established.
                if (outcome.state == usecases::WriteState::Unknown)
                    cams.forgetDeviceTrack(program, write.wanted.output);
            }
        } else if (outcome.actual) {
            assembled[program].number = program;
            if (!outcome.actual->cams.isEmpty())
                assembled[program].tracks.insert(outcome.actual->output, *outcome.actual);
        } else {
            incomplete.insert(program);
        }
    }
    for (auto it = assembled.cbegin(); it != assembled.cend(); ++it) {
        if (!incomplete.contains(it.key())) cams.setDeviceProgram(it.value());
    }
}

// The table interface's own sections: their device copies follow.
void applyTableSections(Workspace& workspace, const usecases::WritePlan& plan,
                        usecases::WriteReport& report) {
    OutcomesByItem<OutputDeadTime> modes(report.deadTimeModes);
    for (const usecases::DeadTimeModeWrite& write : plan.deadTimeModes) {
        const auto actual =
            modes.of(usecases::itemOf(write), usecases::deadTimeModeLabel(write.output)).actual;
        if (!actual) continue;
        workspace.setDeviceDeadTimeMode(write.output, *actual);
    }
    OutcomesByItem<AnalogueCamTrack> analogue(report.analogueCams);
    for (const usecases::AnalogueCamWrite& write : plan.analogueCams) {
        const auto actual =
            analogue.of(usecases::itemOf(write), usecases::analogueCamsLabel(write.wanted.output))
                .actual;
        if (actual) workspace.analogueCams().setDevice(actual->output, *actual);
    }
    if (plan.programmingProgram && !report.programmingProgram)
        report.programmingProgram =
            notSent<ProgrammingProgram>(usecases::programmingProgramLabel());
    if (report.programmingProgram && report.programmingProgram->actual)
        workspace.programmingProgram().setDevice(*report.programmingProgram->actual);
    if (plan.eepromLock && !report.eepromLock)
        report.eepromLock = notSent<bool>(usecases::eepromLockLabel());
    if (report.eepromLock && report.eepromLock->actual)
        workspace.eepromLock().setDevice(*report.eepromLock->actual);
}

}  // namespace

void applyWriteReport(Workspace& workspace, const PlannedWrite& planned,
                      usecases::WriteReport& report) {
    const usecases::WritePlan& plan = planned.plan;
    CamDocument& cams = *workspace.cams();
    for (const auto* outcomes : {&report.settings, &report.linkSettings}) {
        for (const auto& outcome : *outcomes) {
            if (!outcome.actual) continue;
            for (auto it = outcome.actual->cbegin(); it != outcome.actual->cend(); ++it)
                workspace.settings().setDevice(it.key(), *it);
        }
    }
    applyTracks(cams, plan, report);
    OutcomesByItem<qint32> deadTimes(report.deadTimes);
    for (const usecases::DeadTimeWrite& write : plan.deadTimes) {
        const auto actual =
            deadTimes.of(usecases::itemOf(write), usecases::deadTimeLabel(write.output)).actual;
        if (actual) cams.setDeviceDeadTime(write.output, *actual);
    }
    OutcomesByItem<QString> outputNames(report.outputNames);
    for (const usecases::NameWrite& write : plan.outputNames) {
        const auto actual =
            outputNames.of(usecases::outputNameItem(write), usecases::outputNameLabel(write.number))
                .actual;
        if (actual) cams.setDeviceOutputName(write.number, *actual);
    }
    // Users last but one: each changes the numbers the following ones are found by.
    OutcomesByItem<std::optional<User>> users(report.users);
    for (const usecases::UserWrite& write : plan.users) {
        const QString name = write.wanted ? write.wanted->name : QString();
        const auto outcome = users.of(usecases::itemOf(write), usecases::userLabel(name));
        if (!knownAfter(outcome.state) || !outcome.actual) continue;
        workspace.users().setDevice(write.row, write.deviceNumber, *outcome.actual);
    }
    OutcomesByItem<PlcNetwork> networks(report.plcNetworks);
    for (const usecases::PlcWrite& write : plan.plcNetworks) {
        if (const auto actual =
                networks.of(usecases::itemOf(write), usecases::plcLabel(write.wanted)).actual)
            workspace.plc().setDevice(Workspace::plcKey(actual->area, actual->number), *actual);
    }
    applyTableSections(workspace, plan, report);
}

quint64 writeToDevice(QObject* context, DeviceSession* session, Workspace* workspace,
                      const QList<WorkspaceItem>& items,
                      std::function<void(const WriteResult&)> done) {
    PlannedWrite planned = planForItems(*workspace, items);
    // Communication settings among the values (a project's, another
    // device's): asked for by name, or left out (issue 39).
    SystemSettings wanted;
    for (const usecases::SettingsWrite& group : planned.plan.settings) wanted.insert(group.wanted);
    const SystemSettings onDevice = workspace->settings().device();
    if (const SystemSettings link = linkSettingsToAsk(wanted, onDevice); !link.isEmpty()) {
        const std::optional<QStringList> asked =
            askLinkSettings(qobject_cast<QWidget*>(context), link, onDevice);
        if (!asked) {
            if (done)
                done(Error{
                    ErrorKind::Cancelled,
                    QCoreApplication::translate("cambench::DeviceWriter",
                                                "Nothing was written: the write was cancelled."),
                    0});
            return 0;
        }
        planned.plan.linkSettingsAsked = *asked;
    }
    const usecases::WritePlan plan = planned.plan;
    // The plan leaves out what the device copies say the device already
    // holds: it may only go to the device those copies were read from.
    const std::optional<DeviceInfo> copiesFrom = workspace->copiesFrom();
    const bool fingerprintKnown = workspace->copiesFingerprintKnown();
    return runOnCamCon<usecases::WriteReport>(
        session, context,
        QCoreApplication::translate("cambench::DeviceWriter", "Write to the device"),
        [plan, copiesFrom, fingerprintKnown](comm::CamConDevice& device,
                                             comm::JobContext& job) -> WriteResult {
            // The device on the line now, not the one the edits were made for.
            const Result<DeviceInfo> identity = device.readInfo();
            if (!identity) return identity.error();
            if (copiesFrom && !sameDevice(*copiesFrom, identity.value(), fingerprintKnown))
                return Error{ErrorKind::InvalidData, otherDeviceRefusal(*copiesFrom, *identity), 0};
            return usecases::writeItems(device, identity.value(), plan,
                                        usecases::UseCaseProgress::of(job));
        },
        [workspace, planned, done](WriteResult result) {
            if (result) {
                // Our write changed the device's counts of cams and dead times.
                workspace->fingerprintChangedByWrite();
                applyWriteReport(*workspace, planned, result.value());
            }
            if (done) done(result);
        });
}

QString writeSummary(const WriteResult& result) {
    if (!result) return result.error().message.section(QLatin1Char('\n'), 0, 0);
    return result->summary();
}

QString writeDetails(const WriteResult& result) {
    if (!result) return result.error().message.section(QLatin1Char('\n'), 1);
    QStringList notWritten;
    QStringList written;
    for (const usecases::OutcomeLine& line : result->lines()) {
        const bool ok = line.state == usecases::WriteState::Written ||
                        line.state == usecases::WriteState::Unchanged;
        (ok ? written : notWritten) << line.text;
    }
    QString text = notWritten.join(QLatin1Char('\n'));
    if (!written.isEmpty()) {
        if (!text.isEmpty()) text += QLatin1String("\n\n");
        text += written.join(QLatin1Char('\n'));
    }
    return text;
}

void presentWriteResult(QWidget* parent, DeviceSession* session, const QString& title,
                        const WriteResult& result) {
    // The person cancelled before anything was sent: nothing to report.
    if (!result && result.error().kind == ErrorKind::Cancelled) return;
    const bool complete = result && result->complete();
    // The device's own: in a machine, another device's window never shows it.
    session->lastWriteReport().record(title, writeSummary(result), writeDetails(result), complete);
    // Complete, yet with something to know (written to RAM only, ...): said
    // where it cannot be missed, not only in the status bar.
    const bool notes = result && !result->notes.isEmpty();
    if (complete && !notes) return;
    ReportDialog::present(parent, complete ? QMessageBox::Information : QMessageBox::Warning, title,
                          writeSummary(result), writeDetails(result));
}

}  // namespace cambench
