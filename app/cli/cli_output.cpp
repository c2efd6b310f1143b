#include "cli_output.h"

#include "cli_options.h"
#include "exit_codes.h"

#include <QFile>
#include <QSaveFile>

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

Status writeOutput(const QString& path, const QByteArray& data) {
    if (path.isEmpty() || path == QLatin1String("-")) {
        std::fwrite(data.constData(), 1, size_t(data.size()), stdout);
        std::fflush(stdout);
        return success();
    }
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(data) != data.size() || !file.commit()) {
        return Error::invalidData(QStringLiteral("cannot write %1 (%2); check the folder exists "
                                                 "and is writable")
                                      .arg(path, file.errorString()));
    }
    return success();
}

Result<QByteArray> readInputFile(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        return Error::invalidData(
            QStringLiteral("cannot read %1 (%2); check the path").arg(path, file.errorString()));
    }
    return file.readAll();
}

}  // namespace cambench::cli
