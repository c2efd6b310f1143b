#include "compare_programs_dialog.h"

#include "camcon_jobs.h"
#include "program_diff_view.h"
#include "workspace.h"

#include "model/camcon/csv_io.h"
#include "model/camcon/program_diff.h"
#include "model/camcon/project_file.h"
#include "ui/camcon/cameditor/cam_document.h"
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
#include <QPainter>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QSplitter>
#include <QVBoxLayout>

namespace cambench {

namespace {

constexpr int kMaxProgram = 32767;

// A legend entry: the swatch as the diagram draws it, and its meaning.
QWidget* legendEntry(ProgramDiffView::Swatch swatch, const QString& text, const QPalette& palette) {
    QPixmap pixmap(36, 16);
    pixmap.fill(palette.color(QPalette::Base));
    QPainter painter(&pixmap);
    ProgramDiffView::paintSwatch(painter, QRectF(1, 1, 34, 14), swatch, palette);
    painter.end();
    auto* entry = new QWidget;
    auto* layout = new QHBoxLayout(entry);
    layout->setContentsMargins(0, 0, 8, 0);
    auto* icon = new QLabel;
    icon->setPixmap(pixmap);
    layout->addWidget(icon);
    layout->addWidget(new QLabel(text));
    return entry;
}

}  // namespace

CompareProgramsDialog::CompareProgramsDialog(DeviceSession* session, Workspace* workspace,
                                             QWidget* parent)
    : QDialog(parent),
      m_session(session),
      m_workspace(workspace),
      m_compare(new QPushButton(tr("Compare"))),
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
    auto* scroll = new QScrollArea;
    scroll->setWidget(m_view);
    scroll->setWidgetResizable(true);
    m_list->setObjectName(QStringLiteral("differenceList"));
    auto* splitter = new QSplitter;
    splitter->addWidget(scroll);
    splitter->addWidget(m_list);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 1);
    splitter->setSizes({720, 340});

    auto* legend = new QHBoxLayout;
    using Swatch = ProgramDiffView::Swatch;
    legend->addWidget(legendEntry(Swatch::Same, tr("the same in both"), palette()));
    legend->addWidget(legendEntry(Swatch::Changed,
                                  tr("changed: A dashed, B solid, moved edges marked"), palette()));
    legend->addWidget(legendEntry(Swatch::OnlyInA, tr("only in A"), palette()));
    legend->addWidget(legendEntry(Swatch::OnlyInB, tr("only in B"), palette()));
    legend->addStretch();

    auto* actions = new QHBoxLayout;
    actions->addWidget(m_compare);
    actions->addWidget(m_fold);
    actions->addStretch();
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(sides);
    layout->addLayout(actions);
    layout->addWidget(m_summary);
    layout->addWidget(splitter, 1);
    layout->addLayout(legend);
    layout->addWidget(buttons);
    resize(1100, 640);

    connect(m_compare, &QPushButton::clicked, this, &CompareProgramsDialog::compare);
    connect(m_fold, &QCheckBox::toggled, m_view, &ProgramDiffView::setFoldUnchanged);
    connect(m_list, &QListWidget::currentRowChanged, m_view, &ProgramDiffView::setSelected);
    connect(m_view, &ProgramDiffView::differenceClicked, m_list,
            [this](int row) { m_list->setCurrentRow(row); });
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
            done(Loaded{cams->program(number), tr("edited on this PC, program %1").arg(number)});
            return;
        }
        case Source::Device: {
            ++m_reading;
            runOnCamCon<CamProgram>(
                m_session, this, tr("Read program %1").arg(number),
                [number](comm::CamConDevice& device, comm::JobContext& job) -> Result<CamProgram> {
                    const Result<DeviceInfo> info = device.readInfo();
                    if (!info) return info.error();
                    if (number >= info->programs)
                        return Error::usage(
                            tr("The device has programs 0 to %1 only.").arg(info->programs - 1));
                    Result<CamProgram> read = device.readProgram(
                        number, info->outputs,
                        [&job](qint64 n, qint64 total) { job.progress(n, total); });
                    if (!read) return read.error();
                    CamProgram program = std::move(read).value();
                    program.number = number;
                    return program;
                },
                [this, number, done](Result<CamProgram> program) {
                    --m_reading;
                    if (!program) {
                        done(program.error());
                        return;
                    }
                    done(Loaded{*program, tr("the device, program %1, read at %2")
                                              .arg(number)
                                              .arg(QTime::currentTime().toString(
                                                  QStringLiteral("HH:mm:ss")))});
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
                    done(
                        Loaded{program,
                               tr("%1, program %2").arg(QFileInfo(w.file).fileName()).arg(number)});
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
            done(Loaded{program, QFileInfo(w.file).fileName()});
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
    m_summary->setText(tr("Reading…"));
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
    m_summary->setText(message);
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
    m_list->clear();
    for (const CamDifference& difference : diff.cams) m_list->addItem(differenceText(difference));
    m_summary->setText(tr("A: %1. B: %2. %n difference(s).", nullptr, int(diff.cams.size()))
                           .arg(a.label, b.label));
    Q_EMIT compared(true);
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
