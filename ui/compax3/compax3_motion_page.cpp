#include "compax3_motion_page.h"

#include "ui/device_session.h"
#include "ui/live_freshness.h"
#include "ui/motion_stop.h"
#include "ui/sentence.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <memory>
#include <utility>

namespace cambench {

using comm::Compax3Motion;

namespace {

QDoubleSpinBox* numberBox(const char* name, double min, double max, double value) {
    auto* box = new QDoubleSpinBox;
    box->setObjectName(QLatin1String(name));
    box->setRange(min, max);
    box->setDecimals(3);
    box->setValue(value);
    box->setMinimumWidth(140);
    return box;
}

// What a motion command changes besides a set: the control word and the
// drive's state, read again on the Objects page so that it does not keep
// the state from before as the drive's.
QList<Compax3ObjectId> statusObjects() {
    return {comm::kCompax3ControlWord, comm::kCompax3StatusWord, comm::kCompax3LastError,
            comm::kCompax3Position, comm::kCompax3LastSet};
}

}  // namespace

Compax3MotionPage::Compax3MotionPage(DeviceSession* session, QWidget* parent)
    : Compax3Page(session, parent),
      m_axis(new QLabel),
      m_set(new QSpinBox),
      m_target(numberBox("compax3Target", -1000000, 1000000, 100)),
      m_velocity(numberBox("compax3Velocity", 0, 100000, 100)),
      m_acceleration(numberBox("compax3Acceleration", 0, 10000000, 1000)),
      m_deceleration(numberBox("compax3Deceleration", 0, 10000000, 1000)),
      m_mode(new QLabel) {
    setObjectName(QStringLiteral("compax3MotionPage"));
    m_axis->setObjectName(QStringLiteral("compax3MotionAxis"));
    QFont big = m_axis->font();
    big.setPointSizeF(big.pointSizeF() * 1.4);
    big.setBold(true);
    m_axis->setFont(big);
    m_set->setObjectName(QStringLiteral("compax3Set"));
    m_set->setRange(0, comm::kCompax3LastSetNumber);
    m_set->setValue(1);
    m_set->setSpecialValueText(tr("0 (homing)"));

    // Big, always on the page; moves are offered only while it can reach the
    // device. A change of the STOP's reach re-decides only whether motions
    // are offered; the set is read when the drive's facts change. (Reading
    // it on every change of the STOP's reach sent a Compax3 request to the
    // CamCon a family switch had just connected.)
    m_stop = makeShellStop(QStringLiteral("compax3Stop"),
                           tr("Stops the drive and drops what waits for the line: the STOP "
                              "above every page. Escape does the same."),
                           [this] { offerMotion(); });

    auto button = [this](const QString& text, const char* name) {
        auto* b = new QPushButton(text);
        b->setObjectName(QLatin1String(name));
        m_actions << b;
        return b;
    };
    QPushButton* enable = button(tr("Enable…"), "compax3Enable");
    QPushButton* disable = button(tr("Disable"), "compax3Disable");
    QPushButton* jogPlus = button(tr("Jog +…"), "compax3JogPlus");
    QPushButton* jogMinus = button(tr("Jog −…"), "compax3JogMinus");
    QPushButton* move = button(tr("Start set…"), "compax3Move");
    connect(enable, &QPushButton::clicked, this, [this] { runMotion(Compax3Motion::Enable); });
    connect(disable, &QPushButton::clicked, this, [this] { runMotion(Compax3Motion::Disable); });
    connect(jogPlus, &QPushButton::clicked, this, [this] { runMotion(Compax3Motion::JogPlus); });
    connect(jogMinus, &QPushButton::clicked, this, [this] { runMotion(Compax3Motion::JogMinus); });
    connect(move, &QPushButton::clicked, this, &Compax3MotionPage::moveSet);

    auto* power = new QGroupBox(tr("Power"));
    auto* powerRow = new QHBoxLayout(power);
    powerRow->addWidget(enable);
    powerRow->addWidget(disable);
    powerRow->addStretch(1);
    auto* jog = new QGroupBox(tr("Jog (moves until STOP)"));
    auto* jogRow = new QHBoxLayout(jog);
    jogRow->addWidget(jogMinus);
    jogRow->addWidget(jogPlus);
    jogRow->addStretch(1);
    auto* set = new QGroupBox(tr("Positioning set"));
    auto* form = new QFormLayout(set);
    form->setFieldGrowthPolicy(QFormLayout::FieldsStayAtSizeHint);
    form->addRow(tr("Set:"), m_set);
    form->addRow(tr("Target:"), m_target);
    form->addRow(tr("Velocity:"), m_velocity);
    form->addRow(tr("Acceleration:"), m_acceleration);
    form->addRow(tr("Deceleration:"), m_deceleration);
    m_mode->setObjectName(QStringLiteral("compax3SetMode"));
    form->addRow(tr("Mode (1905.n):"), m_mode);
    form->addRow(QString(), move);
    connect(m_set, &QSpinBox::valueChanged, this, &Compax3MotionPage::readSet);
    auto* note =
        new QLabel(tr("Every motion asks first. A command that moves the axis is sent "
                      "once: when its answer is lost, CamBench reads the drive's state "
                      "and says it instead of sending it again."));
    note->setWordWrap(true);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_axis);
    layout->addWidget(m_stop);
    layout->addWidget(power);
    layout->addWidget(jog);
    layout->addWidget(set);
    layout->addWidget(note);
    layout->addWidget(freshnessLine());
    layout->addWidget(resultLine());
    layout->addStretch(1);
    factsChanged();
}

QString Compax3MotionPage::axisText() const {
    return m_axis->text();
}

void Compax3MotionPage::offerMotion() {
    const bool known = facts().known;
    // A motion is offered only while the STOP can reach the drive.
    const bool stoppable = session()->motionStop()->armed();
    for (QPushButton* action : m_actions) action->setEnabled(known && stoppable);
    if (!known)
        m_axis->setText(tr("No drive connected."));
    else if (!stoppable)
        showResult(tr("Motion is off while the STOP cannot reach the drive."), false);
}

void Compax3MotionPage::factsChanged() {
    const bool known = facts().known;
    offerMotion();
    m_read.reset();
    m_mode->setText(tr("not read"));
    if (known) readSet();
}

void Compax3MotionPage::readSet() {
    m_read.reset();
    m_mode->setText(tr("not read"));
    if (!facts().known) return;
    const int set = m_set->value();
    session()->run<comm::Compax3Device, comm::Compax3SetValues>(
        this, tr("Read set %1").arg(set),
        [set](comm::Compax3Device& device, comm::JobContext&) { return device.readSet(set); },
        [this, set](Result<comm::Compax3SetValues> values) {
            if (set != m_set->value()) return;  // another set was chosen meanwhile
            if (!values) {
                showResult(
                    tr("Set %1 not read: %2").arg(set).arg(asSentence(values.error().message)),
                    false);
                return;
            }
            showSet(*values);
        });
}

void Compax3MotionPage::showSet(const comm::Compax3SetValues& values) {
    m_read = values;
    m_target->setValue(values.target);
    m_velocity->setValue(values.velocity);
    m_acceleration->setValue(values.acceleration);
    m_deceleration->setValue(values.deceleration);
    m_mode->setText(
        tr("%1 (read at %2)")
            .arg(values.modeText(), values.readAt.toString(QStringLiteral("HH:mm:ss"))));
}

void Compax3MotionPage::setChanged(const comm::Compax3SetValues& now, const QString& note) {
    if (!m_read || now.set != m_read->set || now.set != m_set->value()) return;
    // What the person typed stays; the rest shows the drive's new values.
    const std::pair<QDoubleSpinBox*, std::pair<double, double>> fields[] = {
        {m_target, {m_read->target, now.target}},
        {m_velocity, {m_read->velocity, now.velocity}},
        {m_acceleration, {m_read->acceleration, now.acceleration}},
        {m_deceleration, {m_read->deceleration, now.deceleration}}};
    QList<double> typed;
    for (const auto& field : fields) typed << field.first->value();
    showSet(now);
    for (int i = 0; i < 4; ++i)
        if (typed.at(i) != fields[i].second.first) fields[i].first->setValue(typed.at(i));
    showResult(capitalised(asSentence(note)), false);
    m_askAgain = capitalised(asSentence(note));
    // Asked again once this job's answer is handled.
    QMetaObject::invokeMethod(this, &Compax3MotionPage::moveSet, Qt::QueuedConnection);
}

bool Compax3MotionPage::poll() {
    return pollStatus([this](const comm::Compax3DriveStatus& status) {
        m_stale = false;
        m_shown = status;
        m_axis->setText(capitalised(status.summary()));
        m_axis->setStyleSheet(QString());
    });
}

void Compax3MotionPage::freshnessChanged() {
    if (freshness()->isLive() || !facts().known || !m_shown) return;
    // The motion state is never shown as live when it is not: a missed
    // cycle, a lost line, a backup holding the line.
    m_stale = true;
    m_axis->setText(tr("%1 (%2)").arg(capitalised(m_shown->summary()), freshness()->valueNote()));
    m_axis->setStyleSheet(QStringLiteral("color: gray;"));
}

void Compax3MotionPage::finished(const QString& what,
                                 const Result<comm::Compax3CommandResult>& result) {
    if (!result) {
        showResult(tr("%1: %2").arg(what, asSentence(result.error().message)), false);
        poll();
        return;
    }
    if (!result->note.isEmpty()) {
        if (result->after) m_axis->setText(capitalised(result->after->summary()));
        showResult(capitalised(asSentence(result->note)), false);
        return;
    }
    if (result->after) {
        m_shown = result->after;
        m_axis->setText(capitalised(result->after->summary()));
    }
    // Acknowledged is done, even when the state could not be read after it.
    showResult(tr("Sent: %1. Now %2.").arg(what, result->summary()), true);
}

bool Compax3MotionPage::confirmDisable() {
    return confirm(tr("Disable"), tr("Switch drive %1 powerless?").arg(facts().identity.serial),
                   tr("Power is dropped: the motor no longer holds the axis. A hanging (vertical) "
                      "axis falls unless its brake holds it; a moving axis runs out as the drive "
                      "is set. Make sure nobody is at the axis."));
}

void Compax3MotionPage::runMotion(Compax3Motion motion) {
    if (!facts().known) return;
    const QString what = comm::compax3MotionText(motion);
    if (motion == Compax3Motion::Disable && !confirmDisable()) return;
    if (motion != Compax3Motion::Disable) {
        const QString detail =
            comm::compax3MotionMoves(motion)
                ? tr("The axis moves until STOP (or Escape) is pressed. Make sure nobody is at "
                     "the axis.")
                : tr("The axis is powered and holds its position. Make sure nobody is at the "
                     "axis.");
        const QString title = motion == Compax3Motion::Enable ? tr("Enable") : tr("Jog");
        if (!confirm(title, capitalised(tr("%1 on drive %2?").arg(what, facts().identity.serial)),
                     detail))
            return;
    }
    // Only when the line is free: motion never waits in a queue.
    session()->runMotion<comm::Compax3Device, comm::Compax3CommandResult>(
        this, what,
        [motion](comm::Compax3Device& device, comm::JobContext&) { return device.motion(motion); },
        [this, what](Result<comm::Compax3CommandResult> result) {
            finished(what, result);
            Q_EMIT objectsWritten(statusObjects());
        });
}

void Compax3MotionPage::moveSet() {
    if (!facts().known) return;
    if (!m_read || m_read->set != m_set->value()) {
        showResult(tr("Set %1 is not read from the drive yet: reading it; start it then.")
                       .arg(m_set->value()),
                   false);
        readSet();
        return;
    }
    // Only what the person changed is written; each value named, with the
    // time it was read (the start compares the drive's values with these).
    comm::Compax3SetMove move;
    move.set = m_read->set;
    move.shown = std::make_shared<const comm::Compax3SetValues>(*m_read);
    const QString readAt = m_read->readAt.toString(QStringLiteral("HH:mm:ss"));
    QStringList lines;
    if (!m_askAgain.isEmpty()) lines << std::exchange(m_askAgain, QString()) << QString();
    lines << tr("Set %1 as read from the drive at %2; read again before anything is sent: if the "
                "drive then holds other values, nothing is sent and you are asked again.")
                 .arg(move.set)
                 .arg(readAt)
          << QString();
    auto value = [&lines](const QString& name, double typed, double onDrive,
                          std::optional<double>& into) {
        if (typed != onDrive) {
            into = typed;
            lines << tr("%1: %2 → %3 (written first)")
                         .arg(name, compax3NumberText(onDrive), compax3NumberText(typed));
        } else {
            lines << tr("%1: %2 (as read)").arg(name, compax3NumberText(onDrive));
        }
    };
    if (move.set != 0) value(tr("Target"), m_target->value(), m_read->target, move.target);
    value(tr("Velocity"), m_velocity->value(), m_read->velocity, move.velocity);
    value(tr("Acceleration"), m_acceleration->value(), m_read->acceleration, move.acceleration);
    value(tr("Deceleration"), m_deceleration->value(), m_read->deceleration, move.deceleration);
    lines << tr("Mode (1905.%1): %2 (as read)").arg(move.set).arg(m_read->modeText());
    const QString what = comm::compax3SetMoveText(move);
    if (!confirm(tr("Start"), capitalised(tr("%1 on drive %2?").arg(what, facts().identity.serial)),
                 lines.join(QLatin1Char('\n')) + QStringLiteral("\n\n") +
                     tr("The axis moves to the set's target at its velocity. STOP (or Escape) "
                        "stops it. Make sure nobody is at the axis.")))
        return;
    // Only when the line is free: motion never waits in a queue.
    session()->runMotion<comm::Compax3Device, comm::Compax3CommandResult>(
        this, what,
        [move](comm::Compax3Device& device, comm::JobContext&) { return device.moveSet(move); },
        [this, what, set = move.set](Result<comm::Compax3CommandResult> result) {
            if (result && result->changedSet) {
                setChanged(*result->changedSet, result->note);
                return;
            }
            finished(what, result);
            readSet();  // what the set holds now
            Q_EMIT objectsWritten(statusObjects() +
                                  QList<Compax3ObjectId>{comm::compax3SetTarget(set),
                                                         comm::compax3SetVelocity(set),
                                                         comm::compax3SetAcceleration(set),
                                                         comm::compax3SetDeceleration(set)});
        });
}

}  // namespace cambench
