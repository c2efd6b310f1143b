#include "live_device_page.h"

#include "device_session.h"
#include "live_freshness.h"

#include <QDateTime>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>

namespace cambench {

bool LiveDevicePage::confirm(const QString& title, const QString& question, const QString& detail) {
    QMessageBox box(QMessageBox::Warning, title, question, QMessageBox::Cancel, this);
    box.setObjectName(QStringLiteral("pageConfirm"));
    box.setInformativeText(detail);
    QPushButton* yes = box.addButton(title, QMessageBox::AcceptRole);
    box.setDefaultButton(QMessageBox::Cancel);
    box.exec();
    return box.clickedButton() == yes;
}

void LiveDevicePage::pollAnswered(bool ok) {
    if (ok)
        m_session->freshness()->answered(QDateTime::currentDateTime());
    else
        m_session->freshness()->missed();
}

QLabel* LiveDevicePage::resultLine() {
    if (!m_result) {
        m_result = new QLabel;
        m_result->setObjectName(QStringLiteral("pageResult"));
        m_result->setWordWrap(true);
        m_result->setTextInteractionFlags(Qt::TextSelectableByMouse);
    }
    return m_result;
}

void LiveDevicePage::clearResult() {
    if (!m_result) return;
    m_result->clear();
    m_result->setStyleSheet(QString());
}

void LiveDevicePage::showResult(const QString& text, bool ok) {
    resultLine()->setText(text);
    resultLine()->setStyleSheet(ok ? QString() : QStringLiteral("color: #d03030;"));
    Q_EMIT statusMessage(text);
}

}  // namespace cambench
