#include "mc1_axes_page.h"

#include "mc1_axis_parameters_box.h"

#include "ui/device_session.h"
#include "ui/sentence.h"

#include "comm/mc1/mc1_parameters.h"

#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QShortcut>
#include <QSpinBox>
#include <QVBoxLayout>

namespace cambench {

using comm::Mc1AxisCommand;

namespace {

QSpinBox* valueBox(const char* name) {
    auto* box = new QSpinBox;
    box->setObjectName(QLatin1String(name));
    box->setRange(std::numeric_limits<qint32>::min(), std::numeric_limits<qint32>::max());
    box->setMinimumWidth(120);
    return box;
}

}  // namespace

Mc1AxesPage::Mc1AxesPage(DeviceSession* session, QWidget* parent)
    : Mc1Page(session, parent),
      m_axis(new QSpinBox),
      m_availability(new QLabel),
      m_state(new QLabel),
      m_details(new QLabel),
      m_absolute(valueBox("mc1MoveTo")),
      m_relative(valueBox("mc1MoveBy")),
      m_speed(valueBox("mc1Speed")),
      m_stop(new QPushButton(tr("STOP (Esc)"))),
      m_parameters(new Mc1AxisParametersBox(session)),
      m_axesFound(new QLabel) {
    setObjectName(QStringLiteral("mc1AxesPage"));
    m_axis->setObjectName(QStringLiteral("mc1Axis"));
    m_axis->setRange(comm::kMc1FirstAxis, comm::kMc1LastAxis);
    m_axis->setPrefix(tr("Axis "));
    m_speed->setRange(1, std::numeric_limits<qint32>::max());
    m_speed->setValue(1000);
    m_relative->setValue(100);
    m_state->setObjectName(QStringLiteral("mc1AxisState"));
    QFont big = m_state->font();
    big.setPointSizeF(big.pointSizeF() * 1.4);
    big.setBold(true);
    m_state->setFont(big);
    m_availability->setWordWrap(true);
    m_details->setWordWrap(true);

    // STOP: big, red, always on the page, never disabled while connected.
    m_stop->setObjectName(QStringLiteral("mc1Stop"));
    m_stop->setMinimumHeight(56);
    // Red only while it can stop something: a disabled STOP must not look armed.
    m_stop->setStyleSheet(QStringLiteral(
        "QPushButton { background: #c62828; color: white; font-weight: bold; font-size: 16pt; }"
        "QPushButton:disabled { background: palette(mid); color: palette(dark); }"));
    m_stop->setToolTip(
        tr("Stops every axis with the maximum ramp and drops what waits for the "
           "line. Escape does the same."));
    // While the page is shown, Escape stops from anywhere in the window.
    auto* escape = new QShortcut(QKeySequence(Qt::Key_Escape), this);
    escape->setContext(Qt::WindowShortcut);
    connect(escape, &QShortcut::activated, this, &Mc1AxesPage::stopAll);
    connect(m_stop, &QPushButton::clicked, this, &Mc1AxesPage::stopAll);

    auto* top = new QHBoxLayout;
    top->addWidget(m_axis);
    top->addWidget(m_state, 1);
    auto* moves = new QGroupBox(tr("Move (each asks first)"));
    auto* grid = new QGridLayout(moves);
    const auto addButton = [this, grid](const QString& text, const char* name, int row, int column,
                                        std::function<void()> action) {
        auto* button = new QPushButton(text);
        button->setObjectName(QLatin1String(name));
        grid->addWidget(button, row, column);
        m_motion << button;
        connect(button, &QPushButton::clicked, this, std::move(action));
    };
    addButton(tr("Home"), "mc1Home", 0, 0, [this] { command(Mc1AxisCommand::Home); });
    addButton(tr("Jog −"), "mc1JogMinus", 0, 1, [this] { command(Mc1AxisCommand::JogMinus); });
    addButton(tr("Jog +"), "mc1JogPlus", 0, 2, [this] { command(Mc1AxisCommand::JogPlus); });
    grid->addWidget(m_absolute, 1, 0);
    addButton(tr("Move to"), "mc1MoveToButton", 1, 1,
              [this] { command(Mc1AxisCommand::MoveAbsolute, m_absolute->value()); });
    grid->addWidget(m_relative, 2, 0);
    addButton(tr("Move by"), "mc1MoveByButton", 2, 1,
              [this] { command(Mc1AxisCommand::MoveRelative, m_relative->value()); });
    grid->addWidget(m_speed, 3, 0);
    addButton(tr("Set speed"), "mc1SetSpeed", 3, 1,
              [this] { command(Mc1AxisCommand::SetSpeed, m_speed->value()); });
    addButton(tr("Acknowledge error"), "mc1AckError", 3, 2,
              [this] { command(Mc1AxisCommand::AcknowledgeError); });
    m_motion << m_absolute << m_relative << m_speed << m_axis;

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_stop);
    layout->addWidget(m_availability);
    layout->addWidget(m_parameters);
    m_axesFound->setObjectName(QStringLiteral("mc1AxesFound"));
    layout->addWidget(m_axesFound);
    layout->addLayout(top);
    layout->addWidget(m_details);
    layout->addWidget(moves);
    layout->addStretch();
    layout->addWidget(resultLine());
    connect(m_axis, &QSpinBox::valueChanged, this, [this] {
        m_state->setText(QStringLiteral("—"));
        m_details->clear();
        poll();
    });
    // Values read through another table are not the controller's any more.
    connect(m_parameters, &Mc1AxisParametersBox::tableChanged, this, [this] {
        m_state->setText(QStringLiteral("—"));
        m_details->clear();
        poll();
    });
    factsChanged();
}

int Mc1AxesPage::axis() const {
    return m_axis->value();
}

void Mc1AxesPage::factsChanged() {
    const bool can = facts().known && facts().has(comm::Mc1Capability::Axes);
    for (QWidget* widget : m_motion) widget->setEnabled(can);
    m_stop->setEnabled(can);
    m_availability->setVisible(!can);
    m_availability->setText(facts().known
                                ? tr("The %1 has no axis telegrams: moving axes needs an MC200 V2.")
                                      .arg(comm::mc1VariantName(facts().variant))
                                : tr("Not connected to an MC100/MC200."));
    m_parameters->setVisible(can);
    m_axesFound->setVisible(can);
    if (can) {
        m_parameters->controllerOnLine();
        findAxes();
    }
}

void Mc1AxesPage::findAxes() {
    session()->run<comm::Mc1Device, comm::Mc1Axes>(
        this, tr("Find axes"),
        [](comm::Mc1Device& device, comm::JobContext&) { return device.axes(); },
        [this](Result<comm::Mc1Axes> axes) {
            if (!axes) {
                m_axesFound->setText(tr("Which axes the controller has could not be read: %1")
                                         .arg(axes.error().message));
                return;
            }
            QStringList numbers;
            for (int n : axes->numbers) numbers << QString::number(n);
            m_axesFound->setText(
                numbers.isEmpty()
                    ? tr("The controller has no axes (%1).").arg(axes->source)
                    : tr("Axes %1 (%2).").arg(numbers.join(QStringLiteral(", ")), axes->source));
            if (!axes->numbers.isEmpty())
                m_axis->setRange(axes->numbers.first(), axes->numbers.last());
        });
}

void Mc1AxesPage::showState(const comm::Mc1AxisState& state) {
    m_state->setText(state.summary());
    m_state->setEnabled(true);
    m_details->setText(tr("Position %1 · target %2 · %3 · %4")
                           .arg(state.position)
                           .arg(state.target)
                           .arg(state.homed ? tr("homed") : tr("not homed"))
                           .arg(state.error ? tr("axis error") : tr("no error")));
}

bool Mc1AxesPage::poll() {
    if (!facts().known || !facts().has(comm::Mc1Capability::Axes)) return true;
    const int shown = axis();
    session()->run<comm::Mc1Device, comm::Mc1AxisState>(
        this, tr("Read axis"),
        [shown](comm::Mc1Device& device, comm::JobContext&) { return device.axisState(shown); },
        [this, shown](Result<comm::Mc1AxisState> state) {
            // A refused read (a parameter number the controller does not
            // know) is an answer: the line is alive. A read not sent (an
            // axis it lacks, a number the table lacks) says nothing of it.
            // Either way the page says what was refused and what to load.
            const ErrorKind kind = state ? ErrorKind::None : state.error().kind;
            const bool refused = kind == ErrorKind::DeviceError || kind == ErrorKind::Usage;
            if (kind != ErrorKind::Usage) pollAnswered(state.ok() || refused);
            if (!state) {
                markStale();
                if (refused) {
                    m_state->setText(QStringLiteral("—"));
                    m_details->setText(tr("Not read: %1").arg(state.error().message));
                }
            } else if (shown == axis()) {
                showState(*state);
            }
        },
        comm::JobPriority::Poll, QStringLiteral("mc1-axis"));
    return true;
}

void Mc1AxesPage::markStale() {
    m_state->setEnabled(false);
}

void Mc1AxesPage::command(Mc1AxisCommand command, qint32 value) {
    const int shown = axis();
    const QString what = comm::mc1AxisCommandText(shown, command, value);
    if (comm::mc1AxisCommandMoves(command)) {
        const QString detail =
            command == Mc1AxisCommand::JogPlus || command == Mc1AxisCommand::JogMinus
                ? tr("The axis moves until STOP (or Escape) is pressed.")
                : tr("The axis moves at its set speed. STOP (or Escape) stops it.");
        if (!confirm(
                tr("Move"),
                tr("%1 on the %2?").arg(capitalised(what), comm::mc1VariantName(facts().variant)),
                detail))
            return;
    }
    session()->run<comm::Mc1Device, comm::Mc1AxisDone>(
        this, tr("Axis command"),
        [shown, command, value](comm::Mc1Device& device, comm::JobContext&) {
            return device.axisCommand(shown, command, value);
        },
        [this, what, shown](Result<comm::Mc1AxisDone> done) {
            if (const comm::Mc1AxisState* state = acknowledged(done, what)) {
                if (shown == axis()) showState(*state);
                showResult(tr("Done: %1 (the controller acknowledged it). Now %2.")
                               .arg(capitalised(what), state->summary()),
                           true);
            }
        });
}

void Mc1AxesPage::stopAll() {
    if (!facts().known) return;
    // What waits for the line (a poll, a queued move) goes first.
    session()->worker().cancelAll();
    session()->run<comm::Mc1Device, QStringList>(
        this, tr("STOP"),
        [](comm::Mc1Device& device, comm::JobContext&) -> Result<QStringList> {
            // Every axis the controller has, the stops back to back.
            comm::MotionControl* motion = device.motionControl();
            if (!motion) {
                const Result<comm::Mc1Axes> axes = device.axes();
                return Error::usage(axes ? axes->source : axes.error().message);
            }
            QStringList failed;
            for (const comm::MotionStopLine& line : motion->stopAllMotion().lines)
                if (!line.acknowledged)
                    failed << QStringLiteral("%1: %2").arg(line.what, line.detail);
            if (!failed.isEmpty()) return Error::communication(failed.join(QStringLiteral("; ")));
            return QStringList();
        },
        [this](Result<QStringList> done) {
            showResult(done ? tr("STOP sent to every axis; each acknowledged it.")
                            : tr("STOP did not reach every axis: %1. Use the machine's "
                                 "emergency stop.")
                                  .arg(done.error().message),
                       done.ok());
            poll();
        });
}

}  // namespace cambench
