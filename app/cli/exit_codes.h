#pragma once

#include "model/result.h"

namespace cambench::cli {

// Exit codes of cambench-cli. Scripts depend on these numbers: never renumber.
enum ExitCode {
    ExitOk = 0,
    // The device answered with an error, or cannot do what was asked (its
    // protocol or variant lacks it, or it is not the --variant named), or
    // `verify`: the device differs.
    ExitDevice = 1,
    ExitUsage = 2,          // a command line that cannot be understood
    ExitCommunication = 3,  // no answer, line gone, garbage after all retries, cancelled
    ExitInvalidData = 4,    // a file or value that fails validation
};

inline int exitCodeFor(ErrorKind kind) {
    switch (kind) {
        case ErrorKind::None:
            return ExitOk;
        case ErrorKind::DeviceError:
        case ErrorKind::NotUnderstood:
        case ErrorKind::Unsupported:
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
