#include "cam_page.h"

#include "device_session.h"
#include "report_dialog.h"
#include "workspace.h"

#include "ui/cameditor/cam_diagram_widget.h"
#include "ui/cameditor/cam_document.h"
#include "ui/cameditor/cam_editor_widget.h"

#include <QCoreApplication>
#include <QMessageBox>

#include <QSet>
#include <QVBoxLayout>
#include <algorithm>

namespace cambench {

namespace {

QString camsText(const Track& track) {
    if (track.cams.isEmpty()) return QCoreApplication::translate("cambench::CamPage", "no cams");
    QStringList cams;
    for (const Cam& cam : track.cams) cams << QStringLiteral("%1–%2").arg(cam.on).arg(cam.off);
    return cams.join(QStringLiteral(", "));
}

QString trackKey(int program, int output) {
    return QStringLiteral("track:%1:%2").arg(program).arg(output);
}

}  // namespace

CamPage::CamPage(DeviceSession* session, Workspace* workspace, QWidget* parent)
    : SectionPage(parent),
      m_session(session),
      m_workspace(workspace),
      m_editor(new CamEditorWidget(workspace->cams())) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_editor);
    connect(m_editor, &CamEditorWidget::readProgramRequested, this, [this](int program) {
        readProgram(program, [this, program](const Status& status) {
            if (!status)
                QMessageBox::warning(this, tr("Read program %1").arg(program),
                                     status.error().message);
        });
    });
    connect(m_editor, &CamEditorWidget::writeProgramRequested, this, [this](int program) {
        writeProgram(program, [this, program](const WriteReport& report) {
            if (!report.complete())
                ReportDialog::presentText(this, QMessageBox::Warning,
                                          tr("Write program %1").arg(program), report.details());
        });
    });
    const auto online = [this] { m_editor->setOnline(m_session->isOnline()); };
    connect(m_session, &DeviceSession::stateChanged, this, online);
    online();
}

void CamPage::showStatus(const DeviceStatus& status) {
    m_editor->diagram()->setLivePosition(status.position);
    m_editor->diagram()->setOutputStates(status.outputs);
}

void CamPage::clearLive() {
    m_editor->diagram()->clearLive();
}

void CamPage::readProgram(int program, std::function<void(const Status&)> done) {
    const int outputs = m_workspace->info().outputs;
    Q_EMIT statusMessage(tr("Reading program %1…").arg(program));
    m_session->run<CamProgram>(
        this, tr("Read program %1").arg(program),
        [program, outputs](comm::CamConDevice& client, comm::JobContext& job) {
            return client.readProgram(
                program, outputs, [&job](qint64 done, qint64 total) { job.progress(done, total); });
        },
        [this, program, done](Result<CamProgram> result) {
            if (!result) {
                Q_EMIT statusMessage(tr("Program %1 not read: %2 Your edits are kept.")
                                         .arg(program)
                                         .arg(result.error().message));
                if (done) done(result.error());
                return;
            }
            m_workspace->cams()->loadProgramFromDevice(result.value());
            Q_EMIT statusMessage(tr("Program %1 read.").arg(program));
            if (done) done(success());
        });
}

void CamPage::writeProgram(int program, std::function<void(const WriteReport&)> done) {
    QStringList keys;
    for (const SectionDifference& difference : differences()) {
        if (difference.key.section(QLatin1Char(':'), 1, 1).toInt() == program)
            keys << difference.key;
    }
    const int unchanged = m_workspace->info().outputs -
                          int(std::count_if(keys.cbegin(), keys.cend(), [](const QString& key) {
                              return key.startsWith(QLatin1String("track:"));
                          }));
    writeItems(keys, [this, program, unchanged, done](const WriteReport& written) {
        WriteReport report = written;
        report.unchanged += unchanged;
        Q_EMIT statusMessage(tr("Program %1: %2").arg(program).arg(report.summary()));
        if (done) done(report);
    });
}

QList<SectionDifference> CamPage::differences() const {
    QList<SectionDifference> list;
    const CamDocument* cams = m_workspace->cams();
    QSet<int> withTracks;
    for (const TrackDifference& d : cams->differences()) {
        withTracks.insert(d.program);
        list.append({trackKey(d.program, d.output),
                     tr("Program %1, output %2").arg(d.program).arg(d.output),
                     d.deviceKnown ? camsText(d.deviceTrack) : tr("not read"),
                     camsText(d.editedTrack)});
    }
    // An edited program whose tracks all match differs in its name.
    for (int program : cams->editedPrograms()) {
        if (cams->programState(program) == ChangeState::Edited && !withTracks.contains(program)) {
            list.append({QStringLiteral("name:%1").arg(program), tr("Program %1 name").arg(program),
                         tr("(other name)"), cams->programName(program)});
        }
    }
    return list;
}

void CamPage::writeItems(const QStringList& keys, std::function<void(const WriteReport&)> done) {
    struct Item {
        QString key;
        QString label;
        int program;
        Track track;
        bool isName;
        QString name;
    };
    QList<Item> items;
    QList<int> programs;
    QStringList remaining = keys;
    const CamDocument* cams = m_workspace->cams();
    for (const SectionDifference& d : differences()) {
        if (!keys.isEmpty() && !keys.contains(d.key)) continue;
        remaining.removeAll(d.key);
        const QStringList parts = d.key.split(QLatin1Char(':'));
        const int program = parts.at(1).toInt();
        if (!programs.contains(program)) programs << program;
        if (parts.at(0) == QLatin1String("name")) {
            items.append({d.key, d.item, program, {}, true, cams->programName(program)});
        } else {
            items.append(
                {d.key, d.item, program, cams->track(program, parts.at(2).toInt()), false, {}});
        }
    }
    // A program's name travels with it: write it along when it changed.
    for (int program : programs) {
        const QString key = QStringLiteral("programName:%1").arg(program);
        const bool listed = std::any_of(items.cbegin(), items.cend(), [&](const Item& item) {
            return item.isName && item.program == program;
        });
        if (!listed && cams->hasDeviceCopy(program) &&
            cams->programState(program) == ChangeState::Edited)
            items.append({key,
                          tr("Program %1 name").arg(program),
                          program,
                          {},
                          true,
                          cams->programName(program)});
    }
    WriteReport base;
    base.unchanged = int(remaining.size());
    m_session->run<ItemOutcomes>(
        this, tr("Write cams"),
        [items](comm::CamConDevice& client, comm::JobContext& job) -> Result<ItemOutcomes> {
            ItemOutcomes outcomes;
            int n = 0;
            for (const Item& item : items) {
                job.progress(n++, items.size());
                Status status = Error::cancelled();
                if (!job.cancelled()) {
                    status = item.isName ? client.writeProgramName(item.program, item.name)
                                         : client.writeTrack(item.program, item.track);
                }
                // Old firmware without program names: the cams are what counts.
                if (item.isName && !status && status.error().kind == ErrorKind::NotUnderstood)
                    continue;
                outcomes.append({item.key, item.label, status ? Error{} : status.error()});
            }
            return outcomes;
        },
        [this, base, programs, done](Result<ItemOutcomes> outcomes) {
            WriteReport report = base;
            ItemOutcomes counted;
            for (const ItemOutcome& outcome : outcomes.value()) {
                if (!outcome.key.startsWith(QLatin1String("programName:")))
                    counted << outcome;
                else if (outcome.error.kind != ErrorKind::None)
                    counted << outcome;
            }
            report.add(counted);
            applyWritten(programs, outcomes.value());
            done(report);
        });
}

void CamPage::applyWritten(const QList<int>& programs, const ItemOutcomes& outcomes) {
    CamDocument* cams = m_workspace->cams();
    const QList<TrackDifference> differences = cams->differences();
    for (int program : programs) {
        QList<TrackDifference> failed;
        bool nameFailed = false;
        bool everything = true;
        for (const ItemOutcome& outcome : outcomes) {
            const QStringList parts = outcome.key.split(QLatin1Char(':'));
            if (parts.at(1).toInt() != program || outcome.error.kind == ErrorKind::None) continue;
            everything = false;
            if (parts.at(0) == QLatin1String("track")) {
                for (const TrackDifference& d : differences) {
                    if (d.program == program && d.output == parts.at(2).toInt()) failed << d;
                }
            } else {
                nameFailed = true;
            }
        }
        // Tracks not chosen for this write are still different from the device.
        for (const TrackDifference& d : differences) {
            const QString key = trackKey(program, d.output);
            const bool attempted = std::any_of(outcomes.cbegin(), outcomes.cend(),
                                               [&](const ItemOutcome& o) { return o.key == key; });
            if (d.program == program && !attempted) {
                failed << d;
                everything = false;
            }
        }
        if (everything) {
            cams->markWritten(program);
            continue;
        }
        if (!cams->hasDeviceCopy(program)) continue;  // nothing known to build the device copy from
        // The document records a device copy only as a whole program: give it
        // the device's new state, then put back what did not reach the device.
        CamProgram device = cams->program(program);
        for (const TrackDifference& d : failed) device.tracks.insert(d.output, d.deviceTrack);
        const QString editedName = device.name;
        if (nameFailed) device.name.clear();
        cams->loadProgramFromDevice(device);
        for (const TrackDifference& d : failed) cams->applyTrack(program, d.editedTrack);
        if (nameFailed) cams->applyProgramName(program, editedName);
    }
}

}  // namespace cambench
