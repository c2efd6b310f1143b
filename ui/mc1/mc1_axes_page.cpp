#include "mc1_axes_page.h"

#include "mc1_axis_parameters_box.h"

#include "ui/device_session.h"
#include "ui/motion_stop.h"
#include "ui/sentence.h"

#include "comm/mc1/mc1_parameters.h"

#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
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
    // Said while the moves are off; its place stays when they come on again,
    // so that they do not jump up under the pointer.
    QSizePolicy keepPlace = m_availability->sizePolicy();
    keepPlace.setRetainSizeWhenHidden(true);
    m_availability->setSizePolicy(keepPlace);
    m_details->setWordWrap(true);
    m_details->setObjectName(QStringLiteral("axisDetails"));

    // Big, always on the page; moves are offered only while it can reach the device.
    m_stop = makeShellStop(QStringLiteral("mc1Stop"),
                           tr("Stops every axis and drops what waits for the line: the STOP "
                              "above every page. Escape does the same."),
                           [this] { offerMotion(); });

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
    layout->addWidget(freshnessLine());
    layout->addWidget(resultLine());
    addLiveValue(m_state);
    addLiveValue(m_details);
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

void Mc1AxesPage::offerMotion() {
    const bool axes = facts().known && facts().has(comm::Mc1Capability::Axes);
    // A move is offered only while the STOP can reach the controller.
    const bool can = axes && session()->motionStop()->armed();
    for (QWidget* widget : m_motion) widget->setEnabled(can);
    m_availability->setVisible(!can);
    m_availability->setText(!facts().known ? tr("Not connected to an MC100/MC200.")
                            : !axes
                                ? tr("The %1 has no axis telegrams: moving axes needs an MC200 V2.")
                                      .arg(comm::mc1VariantName(facts().variant))
                                : tr("Moves are off while the STOP cannot reach the %1.")
                                      .arg(comm::mc1VariantName(facts().variant)));
}

void Mc1AxesPage::factsChanged() {
    offerMotion();
    const bool axes = facts().known && facts().has(comm::Mc1Capability::Axes);
    m_parameters->setVisible(axes);
    m_axesFound->setVisible(axes);
    if (axes) {
        m_parameters->controllerOnLine();
        findAxes();
    }
}

QString Mc1AxesPage::headline(const comm::Mc1AxisState& state) const {
    const int jog = state.moving ? m_jogging.value(state.axis) : 0;
    // A jog has no target: the one the controller reports is an earlier move's.
    return jog != 0 ? tr("axis %1 is jogging %2 (now at %3)")
                          .arg(state.axis)
                          .arg(jog > 0 ? QStringLiteral("+") : QStringLiteral("−"))
                          .arg(state.position)
                    : state.summary();
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
    if (!state.moving) m_jogging.remove(state.axis);
    const int jog = m_jogging.value(state.axis);
    m_state->setText(headline(state));
    // One axis standing says nothing of the others.
    reportMotion(state.moving, false, headline(state));
    m_details->setText(
        tr("Position %1 · %2 · %3 · %4")
            .arg(state.position)
            .arg(jog != 0
                     ? tr("jogging %1").arg(jog > 0 ? QStringLiteral("+") : QStringLiteral("−"))
                     : tr("target %1").arg(state.target))
            .arg(state.homed ? tr("homed") : tr("not homed"))
            .arg(state.error ? tr("axis error") : tr("no error")));
}

bool Mc1AxesPage::poll() {
    if (!facts().known || !facts().has(comm::Mc1Capability::Axes)) return true;
    const int shown = axis();
    runPoll<comm::Mc1Device, comm::Mc1AxisState>(
        tr("Read axis"),
        [shown](comm::Mc1Device& device, comm::JobContext&) { return device.axisState(shown); },
        [this, shown](const comm::Mc1AxisState& state) {
            if (shown == axis()) showState(state);
        },
        QStringLiteral("mc1-axis"),
        // A refused read (a parameter number the controller does not know)
        // or one not sent (an axis it lacks, a number the table lacks):
        // the page says what was refused and what to load.
        [this](const Error& error) {
            m_state->setText(QStringLiteral("—"));
            m_details->setText(tr("Not read: %1").arg(error.message));
        });
    return true;
}

void Mc1AxesPage::markStale() {
    // Position, state and details are live values: the page's freshness
    // greys them and says since when there was no answer.
}

void Mc1AxesPage::command(Mc1AxisCommand command, qint32 value) {
    const int shown = axis();
    const QString what = comm::mc1AxisCommandText(shown, command, value);
    if (!confirmCommand(command, what, value)) return;
    DeviceSession::Work<comm::Mc1Device, comm::Mc1AxisDone> work =
        [shown, command, value](comm::Mc1Device& device, comm::JobContext&) {
            return device.axisCommand(shown, command, value);
        };
    std::function<void(Result<comm::Mc1AxisDone>)> answer =
        [this, what, shown, command](Result<comm::Mc1AxisDone> done) {
            // Acknowledged: the jog runs whether or not its read-back came.
            if (done) {
                if (comm::mc1AxisCommandMoves(command)) reportMotionSent(what);
                if (command == Mc1AxisCommand::JogPlus || command == Mc1AxisCommand::JogMinus)
                    m_jogging.insert(shown, command == Mc1AxisCommand::JogPlus ? 1 : -1);
                else if (command != Mc1AxisCommand::SetSpeed)
                    m_jogging.remove(shown);  // another motion, a stop or an acknowledge
            }
            if (const comm::Mc1AxisState* state = acknowledged(done, what)) {
                if (shown == axis()) showState(*state);
                showResult(tr("Done: %1 (the controller acknowledged it). Now %2.")
                               .arg(capitalised(what), headline(*state)),
                           true);
            }
        };
    // A stop goes to the line whatever runs; everything else that acts on
    // an axis only when the line is free (motion never waits in a queue).
    if (command == Mc1AxisCommand::Stop || command == Mc1AxisCommand::QuickStop)
        session()->run(this, tr("Axis command"), std::move(work), std::move(answer));
    else
        session()->runMotion(this, tr("Axis command"), std::move(work), std::move(answer));
}

bool Mc1AxesPage::confirmCommand(Mc1AxisCommand command, const QString& what, qint32 value) {
    const QString controller = comm::mc1VariantName(facts().variant);
    if (command == Mc1AxisCommand::SetSpeed)
        return confirm(
            tr("Set speed"),
            tr("Set the speed of axis %1 to %2 on the %3?").arg(axis()).arg(value).arg(controller),
            tr("The controller moves the axis at this speed from now on."));
    if (!comm::mc1AxisCommandMoves(command)) return true;
    const QString detail = command == Mc1AxisCommand::JogPlus || command == Mc1AxisCommand::JogMinus
                               ? tr("The axis moves until STOP (or Escape) is pressed.")
                               : tr("The axis moves at its set speed. STOP (or Escape) stops it.");
    return confirm(tr("Move"), tr("%1 on the %2?").arg(capitalised(what), controller), detail);
}

}  // namespace cambench
