#include "terminal_page.h"
#include "ui/camcon/camcon_jobs.h"

#include "ui/device_session.h"

#include "comm/traffic/traffic_log.h"

#include <QCheckBox>
#include <QFileDialog>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSaveFile>
#include <QScrollBar>
#include <QSplitter>
#include <QVBoxLayout>

namespace cambench {

namespace {
constexpr int kMaxLogLines = 5000;
}

TerminalPage::TerminalPage(DeviceSession* session, QWidget* parent)
    : CamConSectionPage(parent),
      m_session(session),
      m_command(new QLineEdit),
      m_replies(new QPlainTextEdit),
      m_log(new QPlainTextEdit),
      m_follow(new QCheckBox(tr("Follow"))) {
    const QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    m_command->setPlaceholderText(tr("e.g. ?IFGWG or ?NF000003 — checksum and CR LF are added"));
    m_command->setFont(mono);
    auto* sendButton = new QPushButton(tr("Send"));
    auto* commandRow = new QHBoxLayout;
    commandRow->addWidget(new QLabel(tr("Command:")));
    commandRow->addWidget(m_command, 1);
    commandRow->addWidget(sendButton);

    m_replies->setReadOnly(true);
    m_replies->setFont(mono);
    m_log->setReadOnly(true);
    m_log->setFont(mono);
    m_log->setMaximumBlockCount(kMaxLogLines);
    m_log->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_follow->setChecked(true);

    auto* save = new QPushButton(tr("Save log…"));
    auto* clear = new QPushButton(tr("Clear"));
    auto* logControls = new QHBoxLayout;
    logControls->addWidget(new QLabel(tr("Traffic (user numbers masked)")));
    logControls->addStretch();
    logControls->addWidget(m_follow);
    logControls->addWidget(clear);
    logControls->addWidget(save);

    auto* logBox = new QWidget;
    auto* logLayout = new QVBoxLayout(logBox);
    logLayout->setContentsMargins(0, 0, 0, 0);
    logLayout->addLayout(logControls);
    logLayout->addWidget(m_log);

    auto* splitter = new QSplitter(Qt::Vertical);
    splitter->addWidget(m_replies);
    splitter->addWidget(logBox);
    splitter->setStretchFactor(0, 1);
    splitter->setStretchFactor(1, 2);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(commandRow);
    layout->addWidget(splitter, 1);

    connect(sendButton, &QPushButton::clicked, this, [this] { send(m_command->text()); });
    connect(m_command, &QLineEdit::returnPressed, this, [this] { send(m_command->text()); });
    connect(clear, &QPushButton::clicked, m_log, &QPlainTextEdit::clear);
    connect(save, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Save traffic log"), QString(),
                                                          tr("Text files (*.txt *.log)"));
        if (path.isEmpty()) return;
        const Status saved = saveLog(path);
        if (!saved) QMessageBox::warning(this, tr("Save traffic log"), saved.error().message);
    });
    connect(&m_session->worker(), &comm::JobRunner::traffic, this, &TerminalPage::appendTraffic,
            Qt::QueuedConnection);
}

void TerminalPage::send(const QString& command) {
    const QString text = command.trimmed();
    if (text.size() < 2 || (text.front() != QLatin1Char('?') && text.front() != QLatin1Char('!'))) {
        m_replies->appendPlainText(
            tr("A command starts with ? (query) or ! (command), then its "
               "letters and data, e.g. ?IFGWG."));
        return;
    }
    const QByteArray request = text.toLatin1();
    m_replies->appendPlainText(QStringLiteral("> %1").arg(text));
    runOnCamCon<QByteArray>(
        m_session, this, tr("Terminal"),
        [request](comm::CamConDevice& device, comm::JobContext&) -> Result<QByteArray> {
            if (!device.has(comm::CamConCapability::Terminal))
                return device.missing(comm::CamConCapability::Terminal);
            return device.raw(request);
        },
        [this](Result<QByteArray> reply) {
            if (!reply) {
                m_replies->appendPlainText(tr("< error: %1").arg(reply.error().message));
                return;
            }
            // The device has masked the user numbers already.
            QByteArray shown = ':' + reply.value();
            for (char& c : shown) {
                if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7E)
                    c = '.';
            }
            m_replies->appendPlainText(QStringLiteral("< %1").arg(QString::fromLatin1(shown)));
        });
}

void TerminalPage::appendTraffic(const comm::TrafficEntry& entry) {
    const QString line = comm::formatTrafficEntry(entry);
    if (m_follow->isChecked()) {
        m_log->appendPlainText(line);
    } else {
        // Keep the view where the reader is.
        const int scroll = m_log->verticalScrollBar()->value();
        m_log->appendPlainText(line);
        m_log->verticalScrollBar()->setValue(scroll);
    }
}

QString TerminalPage::logText() const {
    return m_log->toPlainText();
}

Status TerminalPage::saveLog(const QString& path) const {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        return Error::invalidData(tr("Cannot write %1: %2").arg(path, file.errorString()));
    }
    file.write(logText().toUtf8());
    file.write("\n");
    if (!file.commit()) {
        return Error::invalidData(tr("Cannot write %1: %2").arg(path, file.errorString()));
    }
    return success();
}

}  // namespace cambench
