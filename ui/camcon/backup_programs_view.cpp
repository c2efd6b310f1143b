#include "backup_programs_view.h"

#include "compare_programs_dialog.h"
#include "program_diff_view.h"

#include "model/camcon/eeprom_image_file.h"
#include "model/camcon/program_diff.h"
#include "model/camcon/project_content.h"
#include "model/camcon/system_settings.h"

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QSet>
#include <QSplitter>
#include <QVBoxLayout>

#include <algorithm>
#include <optional>

namespace cambench {

namespace {

// The decoded content of the backup at `path`; nothing when it has none.
std::optional<Project> decoded(const QString& path) {
    const Result<EepromImage> image = loadEepromImage(path);
    if (!image || image->content.isEmpty()) return std::nullopt;
    Result<Project> project = projectFromContent(image->content, image->device);
    if (!project) return std::nullopt;
    return std::move(project).value();
}

}  // namespace

BackupProgramsView* BackupProgramsView::create(const QString& olderPath, const QString& olderLabel,
                                               const QString& newerPath,
                                               const QString& newerLabel) {
    std::optional<Project> older = decoded(olderPath);
    std::optional<Project> newer = decoded(newerPath);
    if (!older || !newer) return nullptr;
    auto* view =
        new BackupProgramsView(std::move(*older), olderLabel, std::move(*newer), newerLabel);
    if (!view->programs().isEmpty()) return view;
    delete view;
    return nullptr;
}

BackupProgramsView::BackupProgramsView(Project older, QString olderLabel, Project newer,
                                       QString newerLabel)
    : m_older(std::move(older)),
      m_newer(std::move(newer)),
      m_olderLabel(std::move(olderLabel)),
      m_newerLabel(std::move(newerLabel)),
      m_axis{m_newer.device.minPosition, m_newer.device.maxPosition,
             isRotaryAxis(m_newer.settings)},
      m_choice(new QComboBox),
      m_fold(new QCheckBox(tr("Hide outputs without a difference"))),
      m_summary(new QLabel),
      m_view(new ProgramDiffView),
      m_list(new QListWidget) {
    setObjectName(QStringLiteral("backupProgramsView"));
    QSet<int> numbers;
    for (const Project* project : {&m_older, &m_newer})
        for (const CamProgram& program : project->programs) numbers.insert(program.number);
    QList<int> sorted(numbers.cbegin(), numbers.cend());
    std::sort(sorted.begin(), sorted.end());
    for (int number : sorted) {
        const ProgramDiff diff =
            diffPrograms(programOf(m_older, number), programOf(m_newer, number));
        if (diff.isEmpty()) continue;
        m_numbers << number;
        const QString name = diff.nameB.isEmpty() ? diff.nameA : diff.nameB;
        m_choice->addItem((name.isEmpty() ? tr("Program %1").arg(number)
                                          : tr("Program %1 (%2)").arg(number).arg(name)) +
                              QStringLiteral(": ") +
                              tr("%n difference(s)", nullptr,
                                 int(diff.cams.size()) + (diff.nameDiffers() ? 1 : 0)),
                          number);
    }
    m_choice->setObjectName(QStringLiteral("changedPrograms"));
    m_fold->setChecked(true);
    m_view->setFoldUnchanged(true);
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto* top = new QHBoxLayout;
    top->addWidget(new QLabel(tr("Programs that differ:")));
    top->addWidget(m_choice, 1);
    top->addWidget(m_fold);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(top);
    layout->addWidget(m_summary);
    layout->addWidget(ProgramDiffView::besideList(m_view, m_list, m_fold), 1);
    layout->addLayout(ProgramDiffView::legend(palette()));

    connect(m_choice, &QComboBox::currentIndexChanged, this, &BackupProgramsView::showChoice);
    showChoice(m_choice->currentIndex());
}

CamProgram BackupProgramsView::programOf(const Project& project, int number) {
    for (const CamProgram& program : project.programs)
        if (program.number == number) return program;
    CamProgram none;
    none.number = number;
    return none;
}

void BackupProgramsView::showProgram(int number) {
    const int index = m_choice->findData(number);
    if (index >= 0) m_choice->setCurrentIndex(index);
}

int BackupProgramsView::shownProgram() const {
    return m_choice->currentData().toInt();
}

void BackupProgramsView::showChoice(int index) {
    if (index < 0 || index >= m_numbers.size()) return;
    const int number = m_numbers.at(index);
    const CamProgram a = programOf(m_older, number);
    const CamProgram b = programOf(m_newer, number);
    const ProgramDiff diff = diffPrograms(a, b);
    m_view->setComparison(a, b, diff, m_axis, m_newer.names.outputs);
    m_list->clear();
    for (const CamDifference& difference : diff.cams)
        m_list->addItem(CompareProgramsDialog::differenceText(difference));
    QString text = tr("A: %1, program %2. B: %3, program %2. %n difference(s) of cams.", nullptr,
                      int(diff.cams.size()))
                       .arg(m_olderLabel)
                       .arg(number)
                       .arg(m_newerLabel);
    if (diff.nameDiffers()) text += u' ' + tr("Name \"%1\" → \"%2\".").arg(diff.nameA, diff.nameB);
    m_summary->setText(text);
}

QString BackupProgramsView::summary() const {
    return m_summary->text();
}

}  // namespace cambench
