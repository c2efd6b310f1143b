#include "mc1_program_page.h"

#include "ui/device_session.h"
#include "ui/live_freshness.h"
#include "ui/sentence.h"

#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace cambench {

using comm::Mc1ProgramCommand;

namespace {

// What each command does, for the confirmation; Reset and the flash get a
// plain warning.
QString consequence(Mc1ProgramCommand command) {
    switch (command) {
        case Mc1ProgramCommand::Start:
            return Mc1ProgramPage::tr("The PLC program runs: outputs and axes follow it.");
        case Mc1ProgramCommand::Stop:
            return Mc1ProgramPage::tr(
                "The PLC program stops where it is; outputs keep their state.");
        case Mc1ProgramCommand::Step:
            return Mc1ProgramPage::tr(
                "One instruction of the PLC program runs; it may switch an "
                "output or start an axis.");
        case Mc1ProgramCommand::Reset:
            return Mc1ProgramPage::tr(
                "The controller restarts: axes stop, outputs drop, the PLC "
                "program starts again from the beginning.");
        case Mc1ProgramCommand::FlashSave:
            return Mc1ProgramPage::tr(
                "The controller's flash is overwritten with what it holds now. "
                "What the flash held before is lost.");
        case Mc1ProgramCommand::FlashLoad:
            return Mc1ProgramPage::tr(
                "The controller's variables are replaced by those in its "
                "flash. Values changed since the last save are lost.");
    }
    return {};
}

}  // namespace

Mc1ProgramPage::Mc1ProgramPage(DeviceSession* session, QWidget* parent)
    : Mc1Page(session, parent),
      m_availability(new QLabel),
      m_status(new QLabel),
      m_flags(new QLabel) {
    setObjectName(QStringLiteral("mc1ProgramPage"));
    m_status->setObjectName(QStringLiteral("mc1ProgramStatus"));
    QFont big = m_status->font();
    big.setPointSizeF(big.pointSizeF() * 1.4);
    big.setBold(true);
    m_status->setFont(big);
    m_flags->setObjectName(QStringLiteral("mc1ProgramFlags"));
    m_availability->setWordWrap(true);
    auto* statusBox = new QGroupBox(tr("Status"));
    auto* statusLayout = new QVBoxLayout(statusBox);
    statusLayout->addWidget(m_status);
    statusLayout->addWidget(m_flags);
    auto* controlBox = new QGroupBox(tr("Control (each asks first)"));
    auto* grid = new QGridLayout(controlBox);
    grid->setColumnStretch(1, 1);
    const std::tuple<Mc1ProgramCommand, QString, const char*> commands[] = {
        {Mc1ProgramCommand::Start, tr("Start"), "mc1Start"},
        {Mc1ProgramCommand::Stop, tr("Stop"), "mc1Stop"},
        {Mc1ProgramCommand::Step, tr("Step"), "mc1Step"},
        {Mc1ProgramCommand::Reset, tr("Reset…"), "mc1Reset"},
        {Mc1ProgramCommand::FlashSave, tr("Save to flash…"), "mc1FlashSave"},
        {Mc1ProgramCommand::FlashLoad, tr("Load from flash…"), "mc1FlashLoad"}};
    int row = 0;
    for (const auto& [command, text, name] : commands) {
        auto* button = new QPushButton(text);
        button->setObjectName(QLatin1String(name));
        // What the button does, said before it is pressed (and again in
        // its confirmation).
        auto* does = new QLabel(consequence(command));
        does->setObjectName(QStringLiteral("%1Does").arg(QLatin1String(name)));
        does->setWordWrap(true);
        button->setToolTip(consequence(command));
        grid->addWidget(button, row, 0);
        grid->addWidget(does, row, 1);
        ++row;
        m_buttons << button;
        connect(button, &QPushButton::clicked, this, [this, command = command] { run(command); });
    }
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_availability);
    layout->addWidget(statusBox);
    layout->addWidget(controlBox);
    layout->addStretch();
    layout->addWidget(freshnessLine());
    layout->addWidget(resultLine());
    addLiveValue(m_status);
    addLiveValue(m_flags);
    factsChanged();
}

void Mc1ProgramPage::factsChanged() {
    const bool can = facts().known && facts().has(comm::Mc1Capability::ProgramControl);
    for (QPushButton* button : m_buttons) button->setEnabled(can);
    m_availability->setVisible(!can);
    m_availability->setText(
        facts().known ? tr("The %1 has no program telegrams: status and control need an MC200 V2 "
                           "(SYSDATA). Variables, flags and I/O work.")
                            .arg(comm::mc1VariantName(facts().variant))
                      : tr("Not connected to an MC100/MC200."));
    if (!can) {
        m_status->setText(QStringLiteral("—"));
        m_flags->clear();
    }
}

void Mc1ProgramPage::showStatus(const comm::Mc1ProgramStatus& status) {
    m_status->setText(tr("PLC program: %1").arg(status.summary()));
    m_flags->setText(status.flagTexts().join(QStringLiteral(" · ")));
}

bool Mc1ProgramPage::poll() {
    if (!facts().known || !facts().has(comm::Mc1Capability::ProgramControl)) return true;
    runPoll<comm::Mc1Device, comm::Mc1ProgramStatus>(
        tr("Read program status"),
        [](comm::Mc1Device& device, comm::JobContext&) { return device.programStatus(); },
        [this](const comm::Mc1ProgramStatus& status) { showStatus(status); },
        QStringLiteral("mc1-program"));
    return true;
}

void Mc1ProgramPage::run(Mc1ProgramCommand command) {
    const QString what = comm::mc1ProgramCommandText(command);
    const QString controller = comm::mc1VariantName(facts().variant);
    if (!confirm(capitalised(what), tr("%1 on the %2?").arg(capitalised(what), controller),
                 consequence(command)))
        return;
    using Done = comm::Mc1Done<comm::Mc1ProgramStatus>;
    DeviceSession::Work<comm::Mc1Device, Done> work = [command](comm::Mc1Device& device,
                                                                comm::JobContext&) {
        return device.programCommand(command);
    };
    std::function<void(Result<Done>)> answer = [this, what](Result<Done> done) {
        if (const comm::Mc1ProgramStatus* status = acknowledged(done, what)) {
            showStatus(*status);
            showResult(tr("Done: %1. PLC program %2.").arg(what, status->summary()), true);
        }
    };
    // The program's stop goes whatever runs; a start, a step, a reset, a
    // flash load only when the line is free (never waiting in a queue).
    if (command == Mc1ProgramCommand::Stop)
        session()->run(this, tr("Program command"), std::move(work), std::move(answer));
    else
        session()->runMotion(this, tr("Program command"), std::move(work), std::move(answer));
}

}  // namespace cambench
