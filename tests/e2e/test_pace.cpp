#include "test_pace.h"

#include <QDebug>
#include <QElapsedTimer>
#include <QProcess>

#include "child_process.h"

#include <algorithm>
#include <array>
#include <limits>

namespace cambench::e2e {

namespace {

// `cambench-cli --version` of a Debug build on a quiet machine: under 10 ms
// of CPU time, so about 20 ms from start to end (measured on a 2-core
// machine at load 14: 48..168 ms, median 96). An instrumented build or a
// loaded machine takes longer, and the end-to-end tests' durations grow
// with it.
constexpr double kQuietCliStartMs = 20.0;
// More than this says "something is wrong", not "slow": bounds stay finite.
constexpr double kMostPace = 20.0;

double buildScale() {
    bool ok = false;
    const double scale = qEnvironmentVariable("CAMBENCH_TEST_TIME_SCALE").toDouble(&ok);
    return ok && scale >= 1.0 ? scale : 1.0;
}

// One start of the cli, in ms; a failed start counts as very slow.
double cliStartMs() {
    QProcess process;
    process.setProgram(QStringLiteral(CAMBENCH_CLI_EXE));
    process.setArguments({QStringLiteral("--version")});
    process.setStandardOutputFile(QProcess::nullDevice());
    endWithThisTest(process);
    QElapsedTimer clock;
    clock.start();
    process.start();
    const int bound = int(kQuietCliStartMs * kMostPace * 10);
    if (!process.waitForFinished(bound)) {
        process.kill();
        process.waitForFinished(bound);
        return std::numeric_limits<double>::max();
    }
    return double(clock.elapsed());
}

double measurePace() {
    std::array<double, 3> starts{};
    for (double& start : starts) start = cliStartMs();
    std::sort(starts.begin(), starts.end());
    const double measured = starts[1] / kQuietCliStartMs;
    const double pace = std::clamp(std::max(measured, buildScale()), 1.0, kMostPace);
    qInfo("test pace %.1f (cambench-cli starts in %.0f ms, build scale %.1f)", pace, starts[1],
          buildScale());
    return pace;
}

}  // namespace

double testPace() {
    static const double pace = measurePace();
    return pace;
}

int hangBoundMs(int quietMs) {
    return int(quietMs * testPace());
}

}  // namespace cambench::e2e
