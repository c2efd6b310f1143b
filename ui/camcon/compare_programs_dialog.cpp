#include "compare_programs_dialog.h"

#include "camcon_jobs.h"
#include "device_writer.h"
#include "program_diff_view.h"
#include "workspace.h"

#include "comm/camcon/usecases/program_read.h"
#include "model/camcon/csv_io.h"
#include "model/camcon/program_diff.h"
#include "model/camcon/project_file.h"
#include "ui/camcon/cameditor/cam_document.h"
#include "ui/device_session.h"
#include "ui/sentence.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QSplitter>
#include <QVBoxLayout>

namespace cambench {

namespace {

constexpr int kMaxProgram = 32767;

}  // namespace

CompareProgramsDialog::CompareProgramsDialog(DeviceSession* session, Workspace* workspace,
                                             QWidget* parent)
    : QDialog(parent),
      m_session(session),
      m_workspace(workspace),
      m_compare(new QPushButton(tr("Compare"))),
      m_apply(new QPushButton(tr("Write checked to the device…"))),
      m_fold(new QCheckBox(tr("Hide outputs without a difference"))),
      m_summary(new QLabel),
      m_view(new ProgramDiffView),
      m_list(new QListWidget) {
    setWindowTitle(tr("Compare programs"));
    setObjectName(QStringLiteral("compareProgramsDialog"));
    auto* sides = new QHBoxLayout;
    for (int side = 0; side < 2; ++side) {
        auto* box = new QGroupBox(side == 0 ? tr("A (before)") : tr("B (after)"));
        buildSide(side, box);
        sides->addWidget(box);
    }
    m_sides[1].source->setCurrentIndex(int(Source::Edited));
    m_sides[0].source->setCurrentIndex(
        int(m_session->isOnline() ? Source::Device : Source::ProjectFile));

    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QSplitter* splitter = ProgramDiffView::besideList(m_view, m_list, m_fold);
    splitter->setSizes({720, 340});

    auto* actions = new QHBoxLayout;
    actions->addWidget(m_compare);
    actions->addWidget(m_fold);
    actions->addStretch();
    m_apply->setObjectName(QStringLiteral("applyDifferences"));
    m_apply->setToolTip(
        tr("Writes the checked differences to the device side's program: its outputs as the "
           "device held them, with those differences made like the other side."));
    actions->addWidget(m_apply);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(sides);
    layout->addLayout(actions);
    layout->addWidget(m_summary);
    layout->addWidget(splitter, 1);
    layout->addLayout(ProgramDiffView::legend(palette()));
    layout->addWidget(buttons);
    resize(1100, 640);

    connect(m_compare, &QPushButton::clicked, this, &CompareProgramsDialog::compare);
    connect(m_apply, &QPushButton::clicked, this, &CompareProgramsDialog::applyChecked);
    connect(m_list, &QListWidget::itemChanged, this, &CompareProgramsDialog::updateApply);
    connect(m_session, &DeviceSession::stateChanged, this, &CompareProgramsDialog::updateApply);
    updateApply();
}

void CompareProgramsDialog::buildSide(int side, QWidget* box) {
    SideWidgets& w = m_sides[side];
    w.source = new QComboBox;
    w.source->addItem(tr("Edited on this PC"));
    w.source->addItem(tr("On the device"));
    w.source->addItem(tr("Project file"));
    w.source->addItem(tr("CSV cam file"));
    w.program = new QSpinBox;
    w.program->setRange(0, kMaxProgram);
    w.choose = new QPushButton(tr("Choose…"));
    w.path = new QLabel;
    w.path->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* file = new QHBoxLayout;
    file->addWidget(w.path, 1);
    file->addWidget(w.choose);
    auto* form = new QFormLayout(box);
    form->addRow(tr("Source:"), w.source);
    form->addRow(tr("Program:"), w.program);
    form->addRow(tr("File:"), file);
    connect(w.source, &QComboBox::currentIndexChanged, this, [this, side] { updateSide(side); });
    connect(w.choose, &QPushButton::clicked, this, [this, side] {
        const bool csv = m_sides[side].source->currentIndex() == int(Source::CsvFile);
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Compare programs"), QString(),
            csv ? tr("CSV cam files (*.csv)") : tr("CamBench projects (*.json)"));
        if (path.isEmpty()) return;
        m_sides[side].file = path;
        updateSide(side);
    });
    updateSide(side);
}

void CompareProgramsDialog::updateSide(int side) {
    SideWidgets& w = m_sides[side];
    const auto source = Source(w.source->currentIndex());
    const bool file = source == Source::ProjectFile || source == Source::CsvFile;
    w.choose->setEnabled(file);
    w.path->setText(file ? (w.file.isEmpty() ? tr("(none chosen)") : w.file) : QString());
    // A CSV file holds the cams of one program, without its number.
    w.program->setEnabled(source != Source::CsvFile);
}

void CompareProgramsDialog::setSide(int side, Source source, int program, const QString& path) {
    m_sides[side].file = path;
    m_sides[side].source->setCurrentIndex(int(source));
    m_sides[side].program->setValue(program);
    updateSide(side);
}

CompareProgramsDialog::Source CompareProgramsDialog::sideSource(int side) const {
    return Source(m_sides[side].source->currentIndex());
}

void CompareProgramsDialog::load(int side, std::function<void(Result<Loaded>)> done) {
    const SideWidgets& w = m_sides[side];
    const int number = w.program->value();
    switch (Source(w.source->currentIndex())) {
        case Source::Edited: {
            CamDocument* cams = m_workspace->cams();
            if (!cams->hasDeviceCopy(number) && !cams->editedPrograms().contains(number)) {
                done(Error::usage(tr("Program %1 is not on this PC yet: read it from the device or "
                                     "open a project.")
                                      .arg(number)));
                return;
            }
            done(Loaded{
                cams->program(number), tr("edited on this PC, program %1").arg(number), false, {}});
            return;
        }
        case Source::Device: {
            ++m_reading;
            runOnCamCon<CamProgram>(
                m_session, this, tr("Read program %1").arg(number),
                // The device's identity read now: the program is checked
                // against the device on the line, not against what was read
                // of it before.
                [number](comm::CamConDevice& device, comm::JobContext& job) -> Result<CamProgram> {
                    Result<usecases::ProgramRead> read = usecases::readIdentityAndProgram(
                        device, number, usecases::UseCaseProgress::of(job));
                    if (!read) return read.error();
                    return std::move(read->program);
                },
                [this, number, done](Result<CamProgram> program) {
                    --m_reading;
                    if (!program) {
                        done(program.error());
                        return;
                    }
                    done(Loaded{*program,
                                tr("the device, program %1, read at %2")
                                    .arg(number)
                                    .arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss"))),
                                true, QDateTime::currentDateTimeUtc()});
                });
            return;
        }
        case Source::ProjectFile: {
            if (w.file.isEmpty()) {
                done(Error::usage(tr("Choose the project file.")));
                return;
            }
            const Result<Project> project = loadProject(w.file);
            if (!project) {
                done(project.error());
                return;
            }
            for (const CamProgram& program : project->programs) {
                if (program.number == number) {
                    done(Loaded{program,
                                tr("%1, program %2").arg(QFileInfo(w.file).fileName()).arg(number),
                                false,
                                {}});
                    return;
                }
            }
            done(Error::invalidData(
                tr("%1 holds no program %2.").arg(QFileInfo(w.file).fileName()).arg(number)));
            return;
        }
        case Source::CsvFile: {
            if (w.file.isEmpty()) {
                done(Error::usage(tr("Choose the CSV file.")));
                return;
            }
            const Result<Tracks> tracks = loadCamsCsv(w.file);
            if (!tracks) {
                done(tracks.error());
                return;
            }
            CamProgram program;
            program.tracks = *tracks;
            done(Loaded{program, QFileInfo(w.file).fileName(), false, {}});
            return;
        }
    }
}

void CompareProgramsDialog::compare() {
    // A newer comparison makes what an older one still reads irrelevant.
    const int generation = ++m_generation;
    m_compare->setEnabled(false);
    m_results[0].reset();
    m_results[1].reset();
    m_diff = {};
    m_deviceSide = -1;
    // What was compared before is not shown as if it were still so.
    m_list->clear();
    m_view->setComparison({}, {}, {}, m_workspace->cams()->axis(), {});
    updateApply();
    m_summary->setText(m_pendingNote.isEmpty()
                           ? tr("Reading…")
                           : tr("%1 Reading both sides again…").arg(asSentence(m_pendingNote)));
    // Each side as it arrives; the comparison once both are there.
    for (int side = 0; side < 2; ++side) {
        load(side, [this, side, generation](Result<Loaded> loaded) {
            if (generation != m_generation) return;
            if (!loaded) {
                ++m_generation;  // the other side's answer has nothing to join
                fail(tr("%1: %2").arg(side == 0 ? QStringLiteral("A") : QStringLiteral("B"),
                                      asSentence(loaded.error().message)));
                return;
            }
            m_results[side] = *loaded;
            if (m_results[0] && m_results[1]) showComparison(*m_results[0], *m_results[1]);
        });
    }
}

void CompareProgramsDialog::fail(const QString& message) {
    m_compare->setEnabled(true);
    m_summary->setText(
        m_pendingNote.isEmpty() ? message : asSentence(m_pendingNote) + QLatin1Char(' ') + message);
    m_pendingNote.clear();
    m_list->clear();
    m_view->setComparison({}, {}, {}, m_workspace->cams()->axis(), {});
    Q_EMIT compared(false);
}

void CompareProgramsDialog::showComparison(const Loaded& a, const Loaded& b) {
    m_compare->setEnabled(true);
    // Names are not compared here: a CSV file has none.
    CamProgram left = a.program;
    CamProgram right = b.program;
    left.name.clear();
    right.name.clear();
    const ProgramDiff diff = diffPrograms(left, right);
    QMap<int, QString> names;
    for (int output = 1; output <= m_workspace->info().outputs; ++output)
        names.insert(output, m_workspace->cams()->outputName(output));
    m_view->setComparison(left, right, diff, m_workspace->cams()->axis(), names);
    m_diff = diff;
    // Only a comparison with the device on exactly one side can be applied.
    m_deviceSide = a.fromDevice == b.fromDevice ? -1 : (a.fromDevice ? 0 : 1);
    {
        const QSignalBlocker blocker(m_list);
        m_list->clear();
        for (const CamDifference& difference : diff.cams) {
            auto* item = new QListWidgetItem(differenceText(difference), m_list);
            if (m_deviceSide >= 0) {
                item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
                item->setCheckState(Qt::Unchecked);
            }
        }
    }
    updateApply();
    QString summary =
        tr("A: %1. B: %2. %n difference(s).", nullptr, int(diff.cams.size())).arg(a.label, b.label);
    // After a write, what it did stays said above what the device holds now.
    if (!m_pendingNote.isEmpty()) summary = asSentence(m_pendingNote) + QLatin1Char(' ') + summary;
    m_pendingNote.clear();
    m_summary->setText(summary);
    Q_EMIT compared(true);
}

void CompareProgramsDialog::setChecked(int row, bool checked) {
    if (QListWidgetItem* item = m_list->item(row))
        item->setCheckState(checked ? Qt::Checked : Qt::Unchecked);
}

QList<CamDifference> CompareProgramsDialog::checkedDifferences() const {
    QList<CamDifference> checked;
    for (int row = 0; row < m_list->count() && row < m_diff.cams.size(); ++row) {
        if (m_list->item(row)->checkState() == Qt::Checked) checked << m_diff.cams.at(row);
    }
    return checked;
}

bool CompareProgramsDialog::canApply() const {
    return m_deviceSide >= 0 && m_applying == 0 && m_reading == 0 && m_session->isOnline() &&
           !checkedDifferences().isEmpty();
}

void CompareProgramsDialog::updateApply() {
    m_apply->setVisible(m_deviceSide >= 0);
    m_apply->setEnabled(canApply());
}

void CompareProgramsDialog::applyChecked() {
    if (!canApply()) return;
    const int side = m_deviceSide;
    const QString sideName = side == 0 ? QStringLiteral("A") : QStringLiteral("B");
    const CamProgram device = m_results[side]->program;
    const int number = device.number;
    const QList<CamDifference> checked = checkedDifferences();
    const AppliedDifferences changes =
        applyDifferences(device, side == 0 ? DiffSide::A : DiffSide::B, checked);
    if (!changes.problems.isEmpty() || changes.tracks.isEmpty()) {
        m_applyResult = tr("Nothing written: %1").arg(changes.problems.join(QStringLiteral("; ")));
        m_summary->setText(m_applyResult);
        return;
    }

    // Say exactly what will be written, and what of this PC's it replaces.
    CamDocument* cams = m_workspace->cams();
    QStringList outputs;
    QStringList replacedEdits;
    for (auto it = changes.tracks.cbegin(); it != changes.tracks.cend(); ++it) {
        const int count =
            int(std::count_if(checked.cbegin(), checked.cend(),
                              [&](const CamDifference& d) { return d.output == it.key(); }));
        outputs << tr("output %1 (%n difference(s))", nullptr, count).arg(it.key());
        const Track mine = cams->track(number, it.key());
        if (cams->trackState(number, it.key()) != ChangeState::Unchanged &&
            mine.cams != device.tracks.value(it.key()).cams && mine.cams != it->cams)
            replacedEdits << QString::number(it.key());
    }
    QString text = tr("Write to the device, program %1: %2?")
                       .arg(number)
                       .arg(outputs.join(QStringLiteral(", ")));
    QString details =
        tr("Each output is written whole: as read from the device (%1), with the checked "
           "differences made like the other side. Cam outputs switch as soon as the device "
           "takes them.")
            .arg(m_results[side]->label);
    if (!replacedEdits.isEmpty())
        details += QLatin1String("\n\n") +
                   tr("Output(s) %1 of program %2 hold edits on this PC that are not on the "
                      "device: they are replaced by what is written (Edit → Undo brings them "
                      "back).")
                       .arg(replacedEdits.join(QStringLiteral(", ")))
                       .arg(number);
    QMessageBox box(QMessageBox::Question, tr("Write checked differences"), text,
                    QMessageBox::Cancel, this);
    box.setInformativeText(details);
    QPushButton* write = box.addButton(tr("Write to device"), QMessageBox::AcceptRole);
    box.setDefaultButton(QMessageBox::Cancel);
    box.exec();
    if (box.clickedButton() != write) return;

    // The workspace learns the device's program as just read, takes the
    // new tracks as edits (one undo step), and the one write path writes
    // those outputs with its checks and per-item report.
    cams->setDeviceProgram(device);
    m_workspace->setProgramReadTime(number, m_results[side]->readAt);
    QMap<int, Track> tracks = cams->program(number).tracks;
    QList<WorkspaceItem> items;
    for (auto it = changes.tracks.cbegin(); it != changes.tracks.cend(); ++it) {
        tracks.insert(it.key(), *it);
        items << WorkspaceItem::track(number, it.key());
    }
    cams->replaceTracks(number, tracks, tr("Apply differences from Compare programs"));
    ++m_applying;
    updateApply();
    m_summary->setText(tr("Writing program %1…").arg(number));
    writeToDevice(this, m_session, m_workspace, items, [this, number](const WriteResult& result) {
        --m_applying;
        m_applyResult = tr("Program %1: %2").arg(number).arg(writeSummary(result));
        presentWriteResult(this, m_session, tr("Write checked differences"), result);
        Q_EMIT applied(result && result->complete());
        // Read again: the list shows what the device holds now.
        m_pendingNote = m_applyResult;
        compare();
    });
}

QString CompareProgramsDialog::differenceText(const CamDifference& difference) {
    const auto range = [](const Cam& cam) {
        return QStringLiteral("%1..%2").arg(cam.on).arg(cam.off);
    };
    switch (difference.kind) {
        case CamDifference::Kind::Changed:
            return difference.camA == difference.camB
                       ? tr("output %1, cam %2: %3 → %4")
                             .arg(difference.output)
                             .arg(difference.camA)
                             .arg(range(difference.a), range(difference.b))
                       : tr("output %1, cam %2 (in B %3): %4 → %5")
                             .arg(difference.output)
                             .arg(difference.camA)
                             .arg(difference.camB)
                             .arg(range(difference.a), range(difference.b));
        case CamDifference::Kind::OnlyInA:
            return tr("output %1: cam %2 only in A")
                .arg(difference.output)
                .arg(range(difference.a));
        case CamDifference::Kind::OnlyInB:
            return tr("output %1: cam %2 only in B")
                .arg(difference.output)
                .arg(range(difference.b));
    }
    return {};
}

QStringList CompareProgramsDialog::differenceTexts() const {
    QStringList texts;
    for (int row = 0; row < m_list->count(); ++row) texts << m_list->item(row)->text();
    return texts;
}

QString CompareProgramsDialog::summary() const {
    return m_summary->text();
}

}  // namespace cambench
