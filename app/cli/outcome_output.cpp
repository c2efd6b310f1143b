#include "outcome_output.h"

#include "cli_output.h"
#include "exit_codes.h"

namespace cambench::cli {

int printOutcomeTally(const usecases::OutcomeTally& tally) {
    QString text;
    for (const usecases::OutcomeLine& line : tally.lines())
        if (line.state != usecases::WriteState::Unchanged) text += line.text + QLatin1Char('\n');
    text += tally.summary() + QLatin1Char('\n');
    printOut(text);
    if (tally.complete()) return ExitOk;
    printError(tally.summary());
    return exitCodeFor(tally.firstError().kind);
}

}  // namespace cambench::cli
