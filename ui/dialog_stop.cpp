#include "dialog_stop.h"

#include "clock_time.h"
#include "motion_stop.h"
#include "stop_button.h"
#include "stop_control.h"
#include "stop_shortcut.h"

#include <QApplication>
#include <QDialog>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLayout>
#include <QPushButton>
#include <QWizard>

#include <algorithm>

namespace cambench {

namespace {

QString stopText() {
    return DialogStop::tr("STOP (%1)").arg(StopShortcut::key().toString(QKeySequence::NativeText));
}

}  // namespace

DialogStops::DialogStops(StopControl* stop, QObject* parent) : QObject(parent), m_stop(stop) {
    QCoreApplication::instance()->installEventFilter(this);
    connect(stop, &StopControl::availabilityChanged, this, &DialogStops::equipOpenDialogs);
}

DialogStops::~DialogStops() {
    // Gone with the application (its child): nothing left to watch.
    if (QCoreApplication::instance()) QCoreApplication::instance()->removeEventFilter(this);
}

bool DialogStops::eventFilter(QObject* watched, QEvent* event) {
    // Before the dialog's own showEvent: a message box sizes itself there,
    // with the room the STOP's row takes.
    if (event->type() != QEvent::Show || !watched->isWidgetType()) return false;
    auto* dialog = qobject_cast<QDialog*>(watched);
    if (dialog && dialog->isWindow() && m_stop->available()) DialogStop::equip(dialog, m_stop);
    return false;
}

void DialogStops::equipOpenDialogs() {
    if (!m_stop->available()) return;
    for (QWidget* window : QApplication::topLevelWidgets())
        if (auto* dialog = qobject_cast<QDialog*>(window); dialog && dialog->isVisible())
            DialogStop::equip(dialog, m_stop);
}

DialogStop* DialogStop::of(const QDialog* dialog) {
    return dialog->findChild<DialogStop*>(QString(), Qt::FindDirectChildrenOnly);
}

DialogStop* DialogStop::equip(QDialog* dialog, StopControl* stop) {
    if (of(dialog)) return nullptr;
    return new DialogStop(dialog, stop);
}

DialogStop::DialogStop(QDialog* dialog, StopControl* stop)
    : QFrame(dialog), m_dialog(dialog), m_stop(stop), m_button(new QPushButton(stopText())) {
    setObjectName(QStringLiteral("dialogStop"));
    m_button->setObjectName(QStringLiteral("dialogStopButton"));
    styleAsStop(m_button);
    m_button->setToolTip(tr("Stops every axis and drive CamBench can reach, without a question. "
                            "%1 does the same and closes this dialog.")
                             .arg(StopShortcut::key().toString(QKeySequence::NativeText)));
    // Never the dialog's default button, never where Enter or Space go.
    m_button->setAutoDefault(false);
    m_button->setDefault(false);
    m_button->setFocusPolicy(Qt::NoFocus);
    connect(m_button, &QPushButton::clicked, stop, &StopControl::stopAll);
    connect(stop, &StopControl::availabilityChanged, this, &DialogStop::update);
    connect(stop, &StopControl::stopStarted, this,
            [this] { showReport(tr("STOP sent…"), QString(), true); });
    connect(stop, &StopControl::stopFinished, this, [this](const comm::MotionStopReport& report) {
        showReport(tr("%1 %2").arg(clockTime(m_stop->lastStopTime().time()),
                                   MotionStop::reportSummary(report)),
                   MotionStop::reportText(report), report.allAcknowledged());
    });
    update();
    if (auto* wizard = qobject_cast<QWizard*>(dialog)) {
        // A wizard lays out its own pages and buttons: the STOP is one of them.
        hide();
        wizard->setButton(QWizard::CustomButton3, m_button);
        wizard->setOption(QWizard::HaveCustomButton3);
        return;
    }
    m_report = new QLabel;
    m_report->setObjectName(QStringLiteral("dialogStopReport"));
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(0, 0, 0, 0);
    row->addWidget(m_button);
    row->addWidget(m_report, 1);
    m_button->ensurePolished();
    setFixedHeight(std::max(40, m_button->sizeHint().height()));
    dialog->installEventFilter(this);
    reserveSpace();
    place();
    show();
}

QString DialogStop::reportText() const {
    return m_report ? m_report->text() : m_button->toolTip();
}

void DialogStop::update() {
    m_button->setEnabled(m_stop->armed());
}

void DialogStop::showReport(const QString& line, const QString& whole, bool ok) {
    if (!m_report) {
        m_button->setToolTip(whole.isEmpty() ? line : line + QLatin1Char('\n') + whole);
        return;
    }
    // One line: the row keeps its height whatever the report.
    m_report->setText(
        m_report->fontMetrics().elidedText(line, Qt::ElideRight, std::max(50, m_report->width())));
    m_report->setToolTip(whole.isEmpty() ? line : line + QLatin1Char('\n') + whole);
    m_report->setStyleSheet(ok ? QString() : QStringLiteral("color: #c62828;"));
}

bool DialogStop::eventFilter(QObject* watched, QEvent* event) {
    if (watched == m_dialog) {
        // A message box builds its layout anew when its text changes.
        if (event->type() == QEvent::LayoutRequest) reserveSpace();
        if (event->type() == QEvent::Resize || event->type() == QEvent::LayoutRequest) place();
    }
    return false;
}

void DialogStop::reserveSpace() {
    QLayout* layout = m_dialog->layout();
    if (!layout || layout == m_reserved) return;
    QMargins margins = layout->contentsMargins();
    m_top = margins.top();
    const int room = height() + std::max(6, layout->spacing());
    margins.setTop(m_top + room);
    layout->setContentsMargins(margins);
    m_reserved = layout;
    // The dialog grows by the row; its own widgets keep their size. A
    // dialog of fixed size (a message box) is given the new one.
    if (m_dialog->minimumHeight() == m_dialog->maximumHeight())
        m_dialog->setFixedHeight(m_dialog->height() + room);
    else
        m_dialog->resize(m_dialog->width(), m_dialog->height() + room);
}

void DialogStop::place() {
    // Without a layout of its own the row goes over the dialog's top.
    const QMargins margins = m_reserved ? m_reserved->contentsMargins() : QMargins(9, 9, 9, 9);
    setGeometry(margins.left(), m_reserved ? m_top : margins.top(),
                m_dialog->width() - margins.left() - margins.right(), height());
    raise();
}

}  // namespace cambench
