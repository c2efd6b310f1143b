#include "report_dialog.h"

#include <QApplication>
#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QScreen>
#include <QStyle>
#include <QVBoxLayout>

namespace cambench {

namespace {
// Of the screen's available height, at most this share for the dialog.
constexpr double kMaxScreenShare = 0.8;
}  // namespace

ReportDialog::ReportDialog(QMessageBox::Icon icon, const QString& title, const QString& summary,
                           const QString& details, QWidget* parent)
    : QDialog(parent),
      m_summary(new QLabel(summary)),
      m_details(new QPlainTextEdit(details)),
      m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok)) {
    setWindowTitle(title);
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_details->setReadOnly(true);
    m_details->setVisible(!details.trimmed().isEmpty());
    m_details->setLineWrapMode(QPlainTextEdit::WidgetWidth);

    auto* iconLabel = new QLabel;
    QStyle::StandardPixmap pixmap = QStyle::SP_MessageBoxInformation;
    if (icon == QMessageBox::Warning) pixmap = QStyle::SP_MessageBoxWarning;
    if (icon == QMessageBox::Critical) pixmap = QStyle::SP_MessageBoxCritical;
    if (icon == QMessageBox::Question) pixmap = QStyle::SP_MessageBoxQuestion;
    const int size = style()->pixelMetric(QStyle::PM_MessageBoxIconSize, nullptr, this);
    iconLabel->setPixmap(style()->standardIcon(pixmap, nullptr, this).pixmap(size, size));
    iconLabel->setAlignment(Qt::AlignTop);

    auto* top = new QHBoxLayout;
    top->addWidget(iconLabel);
    top->addWidget(m_summary, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(m_details, 1);
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);

    const QScreen* screen = parent ? parent->screen() : QApplication::primaryScreen();
    const QRect available = screen ? screen->availableGeometry() : QRect(0, 0, 1280, 800);
    const int lines = int(details.count(QLatin1Char('\n'))) + 1;
    const int wanted =
        sizeHint().height() +
        (m_details->isVisible() ? std::min(lines, 20) * fontMetrics().lineSpacing() : 0);
    setMaximumHeight(int(available.height() * kMaxScreenShare));
    resize(std::min(720, available.width()), std::min(wanted, maximumHeight()));
}

QString ReportDialog::summary() const {
    return m_summary->text();
}

QString ReportDialog::details() const {
    return m_details->toPlainText();
}

void ReportDialog::present(QWidget* parent, QMessageBox::Icon icon, const QString& title,
                           const QString& summary, const QString& details) {
    ReportDialog dialog(icon, title, summary, details, parent);
    dialog.exec();
}

void ReportDialog::presentTally(QWidget* parent, const QString& title,
                                const usecases::OutcomeTally& tally) {
    QStringList lines;
    for (const usecases::OutcomeLine& line : tally.lines())
        if (line.state != usecases::WriteState::Unchanged) lines << line.text;
    present(parent, tally.complete() ? QMessageBox::Information : QMessageBox::Warning, title,
            tally.summary(), lines.join(QLatin1Char('\n')));
}

}  // namespace cambench
