#include "programming_program_page.h"
#include "ui/camcon/camcon_jobs.h"

#include "ui/change_marker.h"
#include "ui/device_session.h"
#include "ui/replace_edits_question.h"
#include "workspace.h"

#include "comm/camcon/usecases/value_text.h"

#include <QComboBox>
#include <QDateTime>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

#include <limits>

namespace cambench {

ProgrammingProgramPage::ProgrammingProgramPage(DeviceSession* session, Workspace* workspace,
                                               QWidget* parent)
    : CamConSectionPage(parent),
      m_session(session),
      m_workspace(workspace),
      m_program(new QSpinBox),
      m_mode(new QComboBox),
      m_switchValue(new QSpinBox),
      m_problems(new QLabel),
      m_state(new QLabel) {
    m_program->setRange(0, 32767);
    m_mode->addItem(tr("Slow"), 0);
    m_mode->addItem(tr("Direct (within one cycle)"), 1);
    m_mode->addItem(tr("At the actual value"), 2);
    m_switchValue->setRange(std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
    m_problems->setWordWrap(true);
    auto* intro =
        new QLabel(tr("The table interface reads and writes the cams of this program. "
                      "It need not be the program that runs the machine."));
    intro->setWordWrap(true);
    auto* form = new QFormLayout;
    form->addRow(tr("Program:"), m_program);
    form->addRow(tr("Program selection:"), m_mode);
    form->addRow(tr("Selection actual value:"), m_switchValue);
    QHBoxLayout* buttons = readWriteBar(ReadWriteBar(
        [this] {
            const bool changed = m_workspace->programmingProgram().isChanged();
            if (mayReplaceEdits(this, sectionTitle(), changed ? 1 : 0)) readFromDevice();
        },
        [this] { writeToDevice(); }));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(form);
    layout->addWidget(m_state);
    layout->addLayout(buttons);
    layout->addWidget(m_problems);
    layout->addStretch();
    connect(m_program, &QSpinBox::valueChanged, this, &ProgrammingProgramPage::takeFields);
    connect(m_mode, &QComboBox::currentIndexChanged, this, &ProgrammingProgramPage::takeFields);
    connect(m_switchValue, &QSpinBox::valueChanged, this, &ProgrammingProgramPage::takeFields);
    connect(m_workspace, &Workspace::tableSectionsChanged, this,
            &ProgrammingProgramPage::showCopies);
    showCopies();
}

void ProgrammingProgramPage::takeFields() {
    // Fields never read or loaded are not a value anybody wants.
    if (m_workspace->programmingProgram().value())
        m_workspace->programmingProgram().edit(edited());
    else
        refreshMarks();
}

void ProgrammingProgramPage::showCopies() {
    const std::optional<ProgrammingProgram> shown = m_workspace->programmingProgram().value();
    if (shown && !(*shown == edited())) {
        const QSignalBlocker program(m_program);
        const QSignalBlocker mode(m_mode);
        const QSignalBlocker value(m_switchValue);
        setEdited(*shown);
    }
    refreshMarks();
}

void ProgrammingProgramPage::refreshMarks() {
    const ProgrammingProgram now = edited();
    const std::optional<ProgrammingProgram>& device =
        m_workspace->programmingProgram().deviceValue();
    const auto mark = [](QWidget* field, bool changed, const QString& onDevice) {
        QFont font = field->font();
        font.setBold(changed);
        field->setFont(font);
        field->setToolTip(changed ? tr("On the device: %1").arg(onDevice) : QString());
    };
    m_problems->setText(
        validateProgrammingProgram(now, m_workspace->info()).join(QLatin1Char('\n')));
    if (!device) {
        // Values never read are not the device's: say so instead of
        // showing the fields' zeros as if they were.
        m_state->setText(m_workspace->programmingProgram().isChanged()
                             ? changedMarker() + tr("From the project, not read from the "
                                                    "device: write it or read the device.")
                             : tr("Not read from the device yet: the values shown are not the "
                                  "device's."));
        return;
    }
    mark(m_program, now.program != device->program, QString::number(device->program));
    mark(m_mode, now.selectMode != device->selectMode,
         m_mode->itemText(qMax(0, m_mode->findData(device->selectMode))));
    mark(m_switchValue, now.switchValue != device->switchValue,
         QString::number(device->switchValue));
    const bool changed = !(now == *device);
    m_state->setText(changed ? changedMarker() + tr("Edited, not written to the device.")
                             : tr("As on the device."));
}

ProgrammingProgram ProgrammingProgramPage::edited() const {
    return {m_program->value(), m_mode->currentData().toInt(), m_switchValue->value()};
}

void ProgrammingProgramPage::setEdited(const ProgrammingProgram& programming) {
    m_program->setValue(programming.program);
    m_mode->setCurrentIndex(qMax(0, m_mode->findData(programming.selectMode)));
    m_switchValue->setValue(programming.switchValue);
}

void ProgrammingProgramPage::readFromDevice() {
    runOnCamCon<ProgrammingProgram>(
        m_session, this, tr("Read the programming program"),
        [](comm::CamConDevice& device, comm::JobContext&) {
            return device.readProgrammingProgram();
        },
        [this](Result<ProgrammingProgram> programming) {
            if (!programming) {
                Q_EMIT statusMessage(tr("Reading the programming program failed: %1")
                                         .arg(programming.error().message));
                return;
            }
            // The person chose to replace their edit.
            m_workspace->programmingProgram().merge(*programming, ValueSource::Device, false);
            m_workspace->setReadTime(ProjectPart::ProgrammingProgram,
                                     QDateTime::currentDateTimeUtc());
        });
}

void ProgrammingProgramPage::writeToDevice(std::function<void(const WriteResult&)> done) {
    writeDifferences(m_session, m_workspace, std::move(done));
}

QList<SectionDifference> ProgrammingProgramPage::differences() const {
    if (!m_workspace->programmingProgram().isChanged()) return {};
    const std::optional<ProgrammingProgram>& device =
        m_workspace->programmingProgram().deviceValue();
    return {{WorkspaceItem::programmingProgram(), sectionTitle(),
             device ? usecases::programmingProgramText(*device) : tr("not read"),
             usecases::programmingProgramText(*m_workspace->programmingProgram().value())}};
}

}  // namespace cambench
