#pragma once

#include <QString>

namespace cambench::cli {

// A percentage bar on stderr for long operations, drawn only when stderr is
// a terminal so that scripts and logs get no control characters.
class ProgressBar {
public:
    ProgressBar();
    ~ProgressBar();

    void update(qint64 done, qint64 total, const QString& text);
    void finish();  // ends the bar's line, if one was drawn

private:
    bool m_enabled = false;
    bool m_drawn = false;
    int m_lastPercent = -1;
};

}  // namespace cambench::cli
