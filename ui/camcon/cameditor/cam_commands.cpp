#include "ui/camcon/cameditor/cam_commands.h"

#include "ui/camcon/cameditor/cam_document.h"

namespace cambench {

namespace {
constexpr int kSetCamCommandId = 0x43414d;  // any constant unique among our commands
constexpr quint64 kCellKeyFlag = quint64(1) << 62;
}  // namespace

ReplaceTrackCommand::ReplaceTrackCommand(CamDocument* document, int program, Track before,
                                         Track after, const QString& text)
    : m_document(document),
      m_program(program),
      m_before(std::move(before)),
      m_after(std::move(after)) {
    setText(text);
}

void ReplaceTrackCommand::undo() {
    m_document->applyTrack(m_program, m_before);
}

void ReplaceTrackCommand::redo() {
    m_document->applyTrack(m_program, m_after);
}

SetCamCommand::SetCamCommand(CamDocument* document, int program, Track before, Track after,
                             const QString& text, quint64 mergeKey)
    : ReplaceTrackCommand(document, program, std::move(before), std::move(after), text),
      m_mergeKey(mergeKey) {}

int SetCamCommand::id() const {
    return m_mergeKey != 0 ? kSetCamCommandId : -1;
}

bool SetCamCommand::mergeWith(const QUndoCommand* other) {
    const auto* next = static_cast<const SetCamCommand*>(other);
    if (next->m_mergeKey != m_mergeKey || next->m_program != m_program ||
        next->m_before != m_after) {
        return false;
    }
    m_after = next->m_after;
    // A drag that ends where it started leaves nothing to undo.
    setObsolete(m_after == m_before);
    return true;
}

quint64 SetCamCommand::cellKey(int program, int output, int row, int column) {
    return kCellKeyFlag | (quint64(quint16(program)) << 40) | (quint64(quint16(output)) << 24) |
           (quint64(quint16(row)) << 8) | quint64(quint8(column));
}

ReplaceProgramCommand::ReplaceProgramCommand(CamDocument* document, CamProgram before,
                                             CamProgram after, const QString& text)
    : m_document(document), m_before(std::move(before)), m_after(std::move(after)) {
    setText(text);
}

void ReplaceProgramCommand::undo() {
    m_document->applyProgram(m_before);
}

void ReplaceProgramCommand::redo() {
    m_document->applyProgram(m_after);
}

}  // namespace cambench
