#include "cli_output.h"

#include "exit_codes.h"

#include "model/atomic_file.h"

#include <cstdio>

namespace cambench::cli {

namespace {

thread_local OutputBlock* t_capture = nullptr;
QString g_helpCommand;  // written before the command runs, read only then

void writeRaw(bool toStderr, const QByteArray& bytes) {
    std::FILE* stream = toStderr ? stderr : stdout;
    std::fwrite(bytes.constData(), 1, size_t(bytes.size()), stream);
    std::fflush(stream);
}

// Every line the cli prints passes here: to the stream, or to this
// thread's captured block.
void write(bool toStderr, const QByteArray& bytes) {
    if (t_capture)
        t_capture->append(toStderr, bytes);
    else
        writeRaw(toStderr, bytes);
}

}  // namespace

void OutputBlock::append(bool toStderr, const QByteArray& bytes) {
    if (!m_pieces.isEmpty() && m_pieces.last().first == toStderr)
        m_pieces.last().second += bytes;
    else
        m_pieces.append({toStderr, bytes});
}

// Into this thread's block when its output is captured too (a machine
// backup run inside `machine watch`, whose lines are said only on failure).
void OutputBlock::print() const {
    for (const auto& [toStderr, bytes] : m_pieces) write(toStderr, bytes);
}

CaptureOutput::CaptureOutput(OutputBlock& block) : m_previous(t_capture) {
    t_capture = &block;
}

CaptureOutput::~CaptureOutput() {
    t_capture = m_previous;
}

bool outputCaptured() {
    return t_capture != nullptr;
}

void printError(const QString& message) {
    write(true, QStringLiteral("cambench-cli: %1\n").arg(message).toUtf8());
}

void setHelpCommand(const QString& name) {
    g_helpCommand = name;
}

int reportError(const Error& error) {
    printError(error.message);
    if (error.kind == ErrorKind::Usage) {
        // One line, not the whole help: the error stays the last thing read.
        write(true, (g_helpCommand.isEmpty()
                         ? QStringLiteral("Help: `cambench-cli --help`\n")
                         : QStringLiteral("Help: `cambench-cli help %1`, or `cambench-cli --help` "
                                          "for everything\n")
                               .arg(g_helpCommand))
                        .toUtf8());
    }
    return exitCodeFor(error.kind);
}

void printOut(const QString& text) {
    write(false, text.toUtf8());
}

int printJson(const QJsonDocument& document) {
    printOut(QString::fromUtf8(document.toJson(QJsonDocument::Indented)));
    return ExitOk;
}

Status writeOutput(const QString& path, const QByteArray& data) {
    if (path.isEmpty() || path == QLatin1String("-")) {
        write(false, data);
        return success();
    }
    return writeFileAtomically(path, data);
}

}  // namespace cambench::cli
