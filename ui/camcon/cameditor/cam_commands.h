#pragma once

#include "model/camcon/cam_program.h"

#include <QUndoCommand>

#include <functional>

namespace cambench {

class CamDocument;

// Sets one track of one program; insert, delete, move, generate and copy to
// another output are all this command with a different text.
class ReplaceTrackCommand : public QUndoCommand {
public:
    ReplaceTrackCommand(CamDocument* document, int program, Track before, Track after,
                        const QString& text);
    void undo() override;
    void redo() override;

protected:
    CamDocument* m_document;
    int m_program;
    Track m_before;
    Track m_after;
};

// Changes one cam. Consecutive commands with the same non-zero merge key
// become one undo step: repeated edits of one table cell, or every mouse
// move of one drag in the diagram.
class SetCamCommand : public ReplaceTrackCommand {
public:
    SetCamCommand(CamDocument* document, int program, Track before, Track after,
                  const QString& text, quint64 mergeKey);
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

    // The merge key of a table cell (drag keys come from CamDocument::newDragKey()).
    static quint64 cellKey(int program, int output, int row, int column);

private:
    quint64 m_mergeKey;
};

// Replaces a whole program (copy program to another number).
class ReplaceProgramCommand : public QUndoCommand {
public:
    ReplaceProgramCommand(CamDocument* document, CamProgram before, CamProgram after,
                          const QString& text);
    void undo() override;
    void redo() override;

private:
    CamDocument* m_document;
    CamProgram m_before;
    CamProgram m_after;
};

// A single value with a setter: program name, output name, dead time.
template <class T>
class SetValueCommand : public QUndoCommand {
public:
    using Apply = std::function<void(const T&)>;
    SetValueCommand(T before, T after, Apply apply, const QString& text)
        : m_before(std::move(before)), m_after(std::move(after)), m_apply(std::move(apply)) {
        setText(text);
    }
    void undo() override { m_apply(m_before); }
    void redo() override { m_apply(m_after); }

private:
    T m_before;
    T m_after;
    Apply m_apply;
};

}  // namespace cambench
