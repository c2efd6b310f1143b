#include "connection_status.h"

#include "device_session.h"
#include "live_freshness.h"

#include <QHBoxLayout>
#include <QPushButton>

namespace cambench {

namespace {
const QColor kAlarm(0xb0, 0x3a, 0x2e);
const QColor kGood(0x2e, 0xaa, 0x40);
const QColor kBusy(0xd8, 0x9a, 0x1e);
const QColor kIdle(0x80, 0x80, 0x80);

bool silent(DeviceSession* session) {
    return session->state() == comm::ConnectionState::Connected && session->freshness()->isStale();
}
}  // namespace

ConnectionStrip::ConnectionStrip(DeviceSession* session, QWidget* parent)
    : QFrame(parent),
      m_session(session),
      m_text(new QLabel),
      m_reconnect(new QPushButton(tr("Reconnect now"))) {
    setObjectName(QStringLiteral("connectionStrip"));
    setFrameShape(QFrame::StyledPanel);
    setAutoFillBackground(true);
    m_text->setWordWrap(false);
    m_text->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(8, 4, 8, 4);
    layout->addWidget(m_text, 1);
    layout->addWidget(m_reconnect);
    // Two lines of text and the button, whatever is shown: the pages below
    // never move when the line is lost or comes back.
    const int lines = 2 * fontMetrics().lineSpacing() + 2 * frameWidth() + 12;
    setFixedHeight(std::max(lines, m_reconnect->sizeHint().height() + 8));
    m_reconnect->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
    QSizePolicy keep = m_reconnect->sizePolicy();
    keep.setRetainSizeWhenHidden(true);
    m_reconnect->setSizePolicy(keep);
    connect(m_reconnect, &QPushButton::clicked, m_session, &DeviceSession::reconnect);
    connect(m_session, &DeviceSession::stateChanged, this, &ConnectionStrip::update);
    connect(m_session->freshness(), &LiveFreshness::changed, this, &ConnectionStrip::update);
    connect(m_session, &DeviceSession::deviceCheckedChanged, this, &ConnectionStrip::update);
    connect(m_session, &DeviceSession::identifyProblemChanged, this, &ConnectionStrip::update);
    update();
}

void ConnectionStrip::setIdentity(std::function<QString()> identity) {
    m_identity = std::move(identity);
    update();
}

void ConnectionStrip::resizeEvent(QResizeEvent* event) {
    QFrame::resizeEvent(event);
    showLines();
}

void ConnectionStrip::showLines() {
    const int width = std::max(50, m_text->width());
    QStringList shown;
    for (const QString& line : m_lines) {
        QString fitted = m_text->fontMetrics().elidedText(line, Qt::ElideRight, width);
        if (fitted != line) {
            // Shortened at a word's end, never in the middle of one (the
            // whole text is in the tooltip).
            const int space = int(line.left(fitted.size() - 1).lastIndexOf(QLatin1Char(' ')));
            if (space > 0) fitted = line.left(space) + QChar(0x2026);
        }
        shown << fitted;
    }
    m_text->setText(shown.join(QLatin1Char('\n')));
    m_text->setToolTip(text());
}

void ConnectionStrip::update() {
    const comm::ConnectionState state = m_session->state();
    const QString port = m_session->connection().port;
    const bool lost = state == comm::ConnectionState::Lost || m_session->isRetrying();
    bool failed = false;
    QString text;
    if (lost) {
        text = tr("The connection to %1 is lost.").arg(port);
        if (!m_session->lastMessage().isEmpty())
            text += QLatin1Char(' ') + capitalised(asSentence(m_session->lastMessage()));
        text += QLatin1Char('\n') + tr("CamBench tries again by itself; your edits are kept.");
    } else if (silent(m_session)) {
        text = tr("The device on %1 has not answered since %2.")
                   .arg(port, m_session->freshness()->lastAnswerText()) +
               QLatin1Char('\n') +
               tr("Live values are from then. Check the cable and the device's power; your edits "
                  "are kept.");
    } else if (state == comm::ConnectionState::Connected &&
               !m_session->identifyProblem().isEmpty()) {
        // The port opened, but no device of the protocol's family answers
        // as one: another device, or none.
        failed = true;
        text = tr("%1: %2").arg(m_session->stateText(), asSentence(m_session->identifyProblem())) +
               QLatin1Char('\n') +
               tr("Check that the port and the protocol are this device's; nothing is written "
                  "to it. Your edits are kept.");
    } else if (state == comm::ConnectionState::Connected && !m_session->deviceChecked()) {
        // Until the device on the line has identified itself, no identity
        // from an earlier connect is shown as if it were this one's.
        text = m_session->stateText();
    } else if (state == comm::ConnectionState::Connected) {
        const QString identity = m_identity ? m_identity() : QString();
        text = identity.isEmpty() ? tr("%1; identity not read yet.").arg(m_session->stateText())
                                  : tr("%1: %2").arg(m_session->stateText(), identity);
    } else if (state == comm::ConnectionState::Connecting) {
        text = m_session->stateText();
    } else if (!m_session->lastMessage().isEmpty()) {
        // The last connect failed: said where the user looks, with what to do.
        failed = true;
        text = tr("Not connected to %1: %2")
                   .arg(port.isEmpty() ? tr("(no port given)") : port,
                        asSentence(m_session->lastMessage())) +
               QLatin1Char('\n') +
               tr("Check the port, the cable and the device's power, then connect again; your "
                  "edits are kept.");
    } else {
        text = tr("Offline. What you edit stays on this PC until you connect and write it.");
    }
    m_alarm = lost || failed || silent(m_session);
    m_lines = withoutCommandNames(text).split(QLatin1Char('\n'));
    showLines();
    m_reconnect->setVisible(lost);
    QPalette pal = palette();
    if (m_alarm) {
        pal.setColor(QPalette::Window, kAlarm);
        pal.setColor(QPalette::WindowText, Qt::white);
    } else {
        pal = QPalette();
    }
    setPalette(pal);
    m_text->setPalette(pal);
}

ConnectionIndicator::ConnectionIndicator(DeviceSession* session, QWidget* parent)
    : QLabel(parent), m_session(session) {
    setObjectName(QStringLiteral("connectionIndicator"));
    connect(m_session, &DeviceSession::stateChanged, this, &ConnectionIndicator::update);
    connect(m_session->freshness(), &LiveFreshness::changed, this, &ConnectionIndicator::update);
    // Green only once the device on the line has identified itself.
    connect(m_session, &DeviceSession::deviceCheckedChanged, this, &ConnectionIndicator::update);
    connect(m_session, &DeviceSession::identifyProblemChanged, this, &ConnectionIndicator::update);
    update();
}

void ConnectionIndicator::update() {
    const comm::ConnectionState state = m_session->state();
    QColor color = kIdle;
    m_stateText = m_session->stateText();
    if (state == comm::ConnectionState::Connected) {
        color = !m_session->identifyProblem().isEmpty() ? kAlarm
                : m_session->deviceChecked()            ? kGood
                                                        : kBusy;
        if (silent(m_session)) {
            color = kAlarm;
            m_stateText =
                tr("No answer since %1 (%2)")
                    .arg(m_session->freshness()->lastAnswerText(), m_session->connection().port);
        }
    }
    if (state == comm::ConnectionState::Connecting) color = kBusy;
    if (state == comm::ConnectionState::Lost || m_session->isRetrying()) color = kAlarm;
    setText(QStringLiteral("<span style='color:%1'>●</span> %2")
                .arg(color.name(), m_stateText.toHtmlEscaped()));
    QString tip = m_session->freshness()->describe();
    if (!m_session->lastMessage().isEmpty()) tip += QLatin1Char('\n') + m_session->lastMessage();
    setToolTip(tip);
}

}  // namespace cambench
