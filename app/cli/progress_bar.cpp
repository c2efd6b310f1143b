#include "progress_bar.h"

#include "cli_output.h"

#include <cstdio>

#ifdef Q_OS_WIN
#include <io.h>
#define CAMBENCH_ISATTY _isatty
#define CAMBENCH_FILENO _fileno
#else
#include <unistd.h>
#define CAMBENCH_ISATTY isatty
#define CAMBENCH_FILENO fileno
#endif

namespace cambench::cli {

ProgressBar::ProgressBar()
    : m_enabled(CAMBENCH_ISATTY(CAMBENCH_FILENO(stderr)) != 0 && !outputCaptured()) {}

ProgressBar::~ProgressBar() {
    finish();
}

void ProgressBar::update(qint64 done, qint64 total, const QString& text) {
    if (!m_enabled || total <= 0) return;
    const int percent = int(qBound(qint64(0), done * 100 / total, qint64(100)));
    if (percent == m_lastPercent) return;
    m_lastPercent = percent;
    constexpr int kWidth = 30;
    const int filled = percent * kWidth / 100;
    const QByteArray bar = QByteArray(filled, '#') + QByteArray(kWidth - filled, '.');
    std::fprintf(stderr, "\r[%s] %3d%% %-30.30s", bar.constData(), percent,
                 text.toUtf8().constData());
    std::fflush(stderr);
    m_drawn = true;
}

void ProgressBar::finish() {
    if (!m_drawn) return;
    std::fputc('\n', stderr);
    std::fflush(stderr);
    m_drawn = false;
    m_lastPercent = -1;
}

}  // namespace cambench::cli
