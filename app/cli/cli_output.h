#pragma once

#include "model/result.h"

#include <QByteArray>
#include <QJsonDocument>
#include <QList>
#include <QString>
#include <QStringList>

namespace cambench::cli {

// "cambench-cli: <message>" on stderr.
void printError(const QString& message);
// Prints the error (a usage error: and one line saying where the help is)
// and returns its exit code.
int reportError(const Error& error);
// The command a usage error's help line names (`cambench-cli help NAME`);
// set once, before any command runs.
void setHelpCommand(const QString& name);

void printOut(const QString& text);  // stdout, as UTF-8
// Prints `document` indented on stdout; returns ExitOk.
int printJson(const QJsonDocument& document);

// What one device of a machine printed while it ran on its own thread
// (machine_parallel.h): the pieces in order, each for stdout or stderr,
// printed whole afterwards so that devices running at once never
// interleave their lines.
class OutputBlock {
public:
    void append(bool toStderr, const QByteArray& bytes);
    void print() const;  // the pieces to stdout and stderr, in order

private:
    QList<QPair<bool, QByteArray>> m_pieces;
};

// While it lives, what this thread prints (printOut, printError,
// reportError, writeOutput to stdout) goes into `block` instead.
class CaptureOutput {
public:
    explicit CaptureOutput(OutputBlock& block);
    ~CaptureOutput();
    CaptureOutput(const CaptureOutput&) = delete;
    CaptureOutput& operator=(const CaptureOutput&) = delete;

private:
    OutputBlock* m_previous;
};

// True while this thread's output is captured: a progress bar drawn from
// several threads at once would be garbage, so it draws nothing then.
bool outputCaptured();

// Writes `data` to `path` atomically, or to stdout when `path` is empty or "-".
Status writeOutput(const QString& path, const QByteArray& data);

}  // namespace cambench::cli
