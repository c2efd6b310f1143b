#include "programming_program_page.h"

#include "change_marker.h"
#include "device_session.h"
#include "page_write_report.h"
#include "workspace.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <limits>

namespace cambench {

ProgrammingProgramPage::ProgrammingProgramPage(DeviceSession* session, Workspace* workspace,
                                               QWidget* parent)
    : SectionPage(parent),
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
    auto* read = new QPushButton(tr("Read from device"));
    auto* write = new QPushButton(tr("Write"));
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(read);
    buttons->addWidget(write);
    buttons->addStretch();
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(form);
    layout->addWidget(m_state);
    layout->addLayout(buttons);
    layout->addWidget(m_problems);
    layout->addStretch();
    connect(read, &QPushButton::clicked, this, [this] {
        const bool changed = m_device && !(edited() == *m_device);
        if (mayReplaceEdits(this, sectionTitle(), changed ? 1 : 0)) readFromDevice();
    });
    connect(write, &QPushButton::clicked, this, &ProgrammingProgramPage::writeToDevice);
    connect(m_program, &QSpinBox::valueChanged, this, &ProgrammingProgramPage::refreshEdits);
    connect(m_mode, &QComboBox::currentIndexChanged, this, &ProgrammingProgramPage::refreshEdits);
    connect(m_switchValue, &QSpinBox::valueChanged, this, &ProgrammingProgramPage::refreshEdits);
    refreshEdits();
}

void ProgrammingProgramPage::refreshEdits() {
    const ProgrammingProgram now = edited();
    const auto mark = [](QWidget* field, bool changed, const QString& onDevice) {
        QFont font = field->font();
        font.setBold(changed);
        field->setFont(font);
        field->setToolTip(changed ? tr("On the device: %1").arg(onDevice) : QString());
    };
    if (!m_device) {
        // Values never read are not the device's: say so instead of
        // showing the fields' zeros as if they were.
        m_state->setText(
            tr("Not read from the device yet: the values shown are not the "
               "device's."));
        m_workspace->setPageEdits(sectionTitle(), 0);
        return;
    }
    mark(m_program, now.program != m_device->program, QString::number(m_device->program));
    mark(m_mode, now.selectMode != m_device->selectMode,
         m_mode->itemText(qMax(0, m_mode->findData(m_device->selectMode))));
    mark(m_switchValue, now.switchValue != m_device->switchValue,
         QString::number(m_device->switchValue));
    const bool changed = !(now == *m_device);
    m_state->setText(changed ? changedMarker() + tr("Edited, not written to the device.")
                             : tr("As on the device."));
    m_workspace->setPageEdits(sectionTitle(), changed ? 1 : 0);
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
    m_session->run<ProgrammingProgram>(
        this, tr("Read the programming program"),
        [](comm::CamConDevice& device, comm::JobContext&) {
            return device.readProgrammingProgram();
        },
        [this](Result<ProgrammingProgram> programming) {
            if (!programming) {
                Q_EMIT statusMessage(tr("Reading the programming program failed: %1")
                                         .arg(programming.error().message));
                return;
            }
            m_device = programming.value();
            setEdited(programming.value());
            refreshEdits();
        });
}

void ProgrammingProgramPage::writeToDevice() {
    const ProgrammingProgram programming = edited();
    const QStringList problems = validateProgrammingProgram(programming, m_workspace->info());
    m_problems->setText(problems.join(QLatin1Char('\n')));
    if (!problems.isEmpty()) return;
    m_session->run<ProgrammingProgram>(
        this, tr("Write the programming program"),
        [programming](comm::CamConDevice& device, comm::JobContext&) -> Result<ProgrammingProgram> {
            const Status written = device.writeProgrammingProgram(programming);
            if (!written) return written.error();
            return device.readProgrammingProgram();
        },
        [this](Result<ProgrammingProgram> now) {
            if (!now) {
                Q_EMIT statusMessage(
                    tr("Writing the programming program failed: %1").arg(now.error().message));
                return;
            }
            m_device = now.value();
            setEdited(now.value());
            refreshEdits();
            Q_EMIT statusMessage(tr("Programming program %1 written.").arg(now->program));
        });
}

}  // namespace cambench
