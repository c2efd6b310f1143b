#pragma once

#include <QStringList>

namespace cambench::cli {

// One cambench-cli run on `args` (without the program name) with the
// command groups registered so far: --help, --version, the global options,
// then the command of --family. Returns the exit code.
int runCommandLine(const QStringList& args);

}  // namespace cambench::cli
