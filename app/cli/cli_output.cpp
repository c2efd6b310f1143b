#include "cli_output.h"

#include "cli_options.h"
#include "exit_codes.h"

#include "model/atomic_file.h"

#include <cstdio>

namespace cambench::cli {

void printError(const QString& message) {
    std::fprintf(stderr, "cambench-cli: %s\n", message.toUtf8().constData());
    std::fflush(stderr);
}

int reportError(const Error& error) {
    printError(error.message);
    if (error.kind == ErrorKind::Usage) {
        std::fputs("\n", stderr);
        std::fputs(usageText().toUtf8().constData(), stderr);
    }
    return exitCodeFor(error.kind);
}

void printOut(const QString& text) {
    const QByteArray bytes = text.toUtf8();
    std::fwrite(bytes.constData(), 1, size_t(bytes.size()), stdout);
    std::fflush(stdout);
}

int printJson(const QJsonDocument& document) {
    printOut(QString::fromUtf8(document.toJson(QJsonDocument::Indented)));
    return ExitOk;
}

Status writeOutput(const QString& path, const QByteArray& data) {
    if (path.isEmpty() || path == QLatin1String("-")) {
        std::fwrite(data.constData(), 1, size_t(data.size()), stdout);
        std::fflush(stdout);
        return success();
    }
    return writeFileAtomically(path, data);
}

}  // namespace cambench::cli
