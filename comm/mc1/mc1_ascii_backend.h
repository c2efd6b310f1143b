#pragma once

#include "comm/engine/cr_line_backend.h"

namespace cambench::comm {

// The MC100's ASCII protocol as the request engine's framing backend: a
// request is one line with its CR; the answer is the next line (LF
// dropped), handed up without its CR.
class Mc1AsciiBackend : public CrLineBackend {
public:
    QString describe() const override;
    QString checkHint() const override;
    qint64 requestWireBytes(const Request& request) const override;
    qint64 replyWireBytes(const Request& request) const override;
};

}  // namespace cambench::comm
