#include "cam_page.h"

#include "cam_text.h"
#include "device_reads.h"
#include "timing_bar.h"
#include "ui/device_session.h"
#include "ui/report_dialog.h"
#include "ui/sentence.h"
#include "workspace.h"

#include "ui/camcon/cameditor/cam_diagram_widget.h"
#include "ui/camcon/cameditor/cam_document.h"
#include "ui/camcon/cameditor/cam_editor_widget.h"

#include <QCoreApplication>

#include <QVBoxLayout>
#include <algorithm>

namespace cambench {

namespace {}  // namespace

CamPage::CamPage(DeviceSession* session, Workspace* workspace, QWidget* parent)
    : CamConSectionPage(parent),
      m_session(session),
      m_workspace(workspace),
      m_editor(new CamEditorWidget(workspace->cams())),
      m_timing(new TimingBar(workspace, m_editor)) {
    m_editor->addDiagramBar(m_timing);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_editor);
    connect(m_editor, &CamEditorWidget::readProgramRequested, this, [this](int program) {
        readProgram(program, [this, program](const Status& status) {
            if (!status && status.error().kind != ErrorKind::Cancelled)
                ReportDialog::present(
                    this, QMessageBox::Warning, tr("Read program %1").arg(program),
                    tr("Program %1 was not read. Your edits are kept.").arg(program),
                    status.error().message);
        });
        // The page's Name and Dead time columns are the device's too: read
        // with the program, never left from an earlier read.
        devicereads::readOutputSettings(this, m_session, m_workspace, [this](const Status& status) {
            if (!status && status.error().kind != ErrorKind::Cancelled)
                Q_EMIT statusMessage(
                    tr("Output names and dead times not read: %1 Your edits are kept.")
                        .arg(asSentence(status.error().message)));
        });
    });
    connect(m_editor, &CamEditorWidget::writeProgramRequested, this, [this](int program) {
        writeProgram(program, [this, program](const WriteResult& result) {
            presentWriteResult(this, m_session, tr("Write program %1").arg(program), result);
        });
    });
    const auto online = [this] { m_editor->setOnline(m_session->isOnline()); };
    connect(m_session, &DeviceSession::stateChanged, this, online);
    online();
}

void CamPage::showStatus(const DeviceStatus& status) {
    m_editor->diagram()->setLivePosition(status.position);
    m_editor->diagram()->setOutputStates(status.outputs);
    // ?BSPEED read as positions per second (provisional, docs/protocols/camcon-ascii.md).
    m_timing->setLiveSpeed(double(status.speed));
}

void CamPage::clearLive() {
    m_editor->diagram()->clearLive();
    m_timing->setLiveSpeed(std::nullopt);
}

void CamPage::readProgram(int program, std::function<void(const Status&)> done) {
    const auto report = reportRead(
        tr("Reading program %1…").arg(program),
        [program] { return tr("Program %1 read.").arg(program); },
        tr("Program %1 not read: %2 Your edits are kept.").arg(program).arg(QStringLiteral("%1")));
    devicereads::readProgram(this, m_session, m_workspace, program,
                             [report, done](const Status& status) {
                                 report(status);
                                 if (done) done(status);
                             });
}

void CamPage::writeProgram(int program, std::function<void(const WriteResult&)> done) {
    QList<WorkspaceItem> items;
    for (const SectionDifference& difference : differences()) {
        if (difference.item.program == program) items << difference.item;
    }
    // A program never read is written whole (and its name with it).
    if (!m_workspace->cams()->hasDeviceCopy(program)) items = {WorkspaceItem::programName(program)};
    if (items.isEmpty()) {
        Q_EMIT statusMessage(
            tr("Program %1: nothing to write, the device holds what you see.").arg(program));
        return;
    }
    Q_EMIT statusMessage(tr("Writing program %1…").arg(program));
    // Outputs not sent were already as on the device: counted, not hidden.
    const int tracksSent =
        int(std::count_if(items.cbegin(), items.cend(), [](const WorkspaceItem& item) {
            return item.kind == WorkspaceItem::Kind::Track;
        }));
    const int others =
        m_workspace->cams()->hasDeviceCopy(program) ? m_workspace->info().outputs - tracksSent : 0;
    writeToDevice(this, m_session, m_workspace, items,
                  [this, program, others, done](const WriteResult& result) {
                      QString summary = tr("Program %1: %2").arg(program).arg(writeSummary(result));
                      if (result && others > 0)
                          summary =
                              asSentence(summary) + QLatin1Char(' ') +
                              tr("%n other output(s) were already as on the device and not sent.",
                                 nullptr, others);
                      Q_EMIT statusMessage(summary);
                      if (done) done(result);
                  });
}

QList<SectionDifference> CamPage::differences() const {
    QList<SectionDifference> list;
    const CamDocument* cams = m_workspace->cams();
    for (int program : cams->editedPrograms()) {
        const std::optional<CamProgram> device = cams->deviceProgram(program);
        const QString name = cams->programName(program);
        if (device ? name != device->name : !name.isEmpty()) {
            list.append({WorkspaceItem::programName(program), tr("Program %1 name").arg(program),
                         device ? device->name : tr("not read"), name});
        }
    }
    for (const TrackDifference& d : cams->differences()) {
        list.append({WorkspaceItem::track(d.program, d.output),
                     tr("Program %1, output %2").arg(d.program).arg(d.output),
                     d.deviceKnown ? camsText(d.deviceTrack) : tr("not read"),
                     camsText(d.editedTrack)});
    }
    return list;
}

}  // namespace cambench
