#include "cambus_view_widget.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QTimer>
#include <QVBoxLayout>

namespace cambench {

namespace {
constexpr int kRefreshMs = 250;
// Without news from the worker for this long the view says it is not live.
constexpr qint64 kStaleMs = 1500;
}  // namespace

CamBusView::CamBusView(comm::CamBusMonitorPtr monitor, QWidget* parent)
    : QWidget(parent),
      m_monitor(std::move(monitor)),
      m_summary(new QLabel),
      m_users(new QWidget),
      m_usersLayout(new QHBoxLayout(m_users)),
      m_timer(new QTimer(this)) {
    setObjectName(QStringLiteral("camBusView"));
    m_summary->setObjectName(QStringLiteral("camBusSummary"));
    m_summary->setWordWrap(true);
    m_usersLayout->setContentsMargins(0, 0, 0, 0);
    m_usersLayout->setSpacing(3);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 4, 0, 0);
    auto* title = new QLabel(tr("<b>Cam-BUS</b> as this PC hears it"));
    layout->addWidget(title);
    layout->addWidget(m_summary);
    layout->addWidget(m_users);
    m_sinceNews.start();
    connect(m_timer, &QTimer::timeout, this, &CamBusView::refresh);
    m_timer->start(kRefreshMs);
    refresh();
}

QString CamBusView::summaryText() const {
    return m_summary->text();
}

void CamBusView::refresh() {
    comm::CamBusView view;
    if (!m_monitor || !m_monitor->read(view)) {
        m_lastTokens = -1;
        m_summary->setText(
            tr("Not on a Cam-BUS: connect with the Cam-BUS protocol to see its "
               "users and the token."));
        showUsers({}, false);
        return;
    }
    if (view.nowMs != m_lastNowMs) {
        if (m_lastTokens >= 0 && view.nowMs > m_lastNowMs && !view.users.isEmpty()) {
            const double rounds = double(view.tokens - m_lastTokens) / view.users.size();
            m_roundsPerSecond = rounds * 1000.0 / double(view.nowMs - m_lastNowMs);
        }
        m_lastTokens = view.tokens;
        m_lastNowMs = view.nowMs;
        m_sinceNews.restart();
    }
    const bool live = m_sinceNews.elapsed() < kStaleMs;
    QString text;
    if (!live) {
        text = tr("Not live: nothing heard from the line for %1 s; the users below are the "
                  "last ones heard.")
                   .arg(m_sinceNews.elapsed() / 1000);
    } else if (view.inInitPhase) {
        text = tr("Initialisation phase: the master searches the users (%n found so far).", "",
                  int(view.users.size()));
    } else if (view.users.isEmpty()) {
        text = tr("Listening: no token heard yet.");
    } else {
        text = tr("%n users · master %1 · token with %2 · %3 rounds/s", "", int(view.users.size()))
                   .arg(view.master)
                   .arg(view.tokenHolder)
                   .arg(m_roundsPerSecond, 0, 'f', 0);
    }
    text += QLatin1Char('\n') +
            tr("Initialisation phases heard since connecting: %1").arg(view.initPhases);
    m_summary->setText(text);
    showUsers(view, live);
}

void CamBusView::showUsers(const comm::CamBusView& view, bool live) {
    const QList<int> numbers = view.users.keys();
    const int holder = live ? view.tokenHolder : -1;
    if (numbers != m_shown) {
        while (QLayoutItem* item = m_usersLayout->takeAt(0)) {
            delete item->widget();
            delete item;
        }
        for (int number : numbers) {
            auto* box = new QLabel(QString::number(number));
            box->setObjectName(QStringLiteral("camBusUser%1").arg(number));
            box->setAlignment(Qt::AlignCenter);
            box->setMinimumWidth(box->fontMetrics().horizontalAdvance(QStringLiteral("00")) + 12);
            box->setFrameShape(QFrame::StyledPanel);
            box->setAutoFillBackground(true);
            m_usersLayout->addWidget(box);
        }
        m_usersLayout->addStretch();
        m_shown = numbers;
    }
    const int own = m_ownNumber ? m_ownNumber() : -1;
    for (int number : numbers) {
        auto* box = m_users->findChild<QLabel*>(QStringLiteral("camBusUser%1").arg(number));
        if (!box) continue;
        const comm::CamBusUserState& user = view.users[number];
        QPalette palette = this->palette();
        const bool token = number == holder;
        palette.setColor(QPalette::Window,
                         palette.color(token ? QPalette::Highlight : QPalette::Button));
        QPalette::ColorGroup group = user.answers && live ? QPalette::Active : QPalette::Disabled;
        palette.setColor(
            QPalette::WindowText,
            palette.color(group, token ? QPalette::HighlightedText : QPalette::ButtonText));
        box->setPalette(palette);
        QString label = QString::number(number);
        if (number == view.master) label += QStringLiteral(" M");
        if (number == own) label += QStringLiteral(" PC");
        box->setText(label);
        QStringList tip{tr("User %1").arg(number)};
        if (number == view.master) tip << tr("master: passes the token");
        if (number == own) tip << tr("this PC");
        if (!user.answers)
            tip << tr(
                "does not answer (stays in the table until the next "
                "initialisation phase)");
        box->setToolTip(tip.join(QStringLiteral("; ")));
    }
    m_highlighted = holder;
}

}  // namespace cambench
