#pragma once

#include "model/result.h"

namespace cambench::cli {

// Exit codes of cambench-cli. Scripts depend on these numbers: never renumber.
enum ExitCode {
    ExitOk = 0,
    ExitDevice = 1,         // the device answered with an error (or `verify`: the device differs)
    ExitUsage = 2,          // wrong command line
    ExitCommunication = 3,  // no answer, line gone, garbage after all retries, cancelled
    ExitInvalidData = 4,    // a file or value that fails validation
};

inline int exitCodeFor(ErrorKind kind) {
    switch (kind) {
        case ErrorKind::None:
            return ExitOk;
        case ErrorKind::DeviceError:
        case ErrorKind::NotUnderstood:
            return ExitDevice;
        case ErrorKind::Communication:
        case ErrorKind::Cancelled:
            return ExitCommunication;
        case ErrorKind::InvalidData:
            return ExitInvalidData;
        case ErrorKind::Usage:
            return ExitUsage;
    }
    return ExitCommunication;
}

}  // namespace cambench::cli
