#pragma once

// Backing up every device of a Multiuser line into one folder, and checking
// them against it later (issue 9). One image per device, named by device
// number and identity, and a manifest (model/camcon/line_manifest.h) that
// is rewritten after every device, so that a run cut in the middle leaves
// a manifest of what was saved. A device that fails is recorded and the
// run goes on.

#include "comm/usecases/use_case_progress.h"

#include "comm/camcon/camcon_device.h"
#include "model/camcon/line_manifest.h"

#include <QList>
#include <QString>

#include <functional>

namespace cambench::usecases {

// Progress of one device of the line: the GUI shows one bar per device.
using DeviceProgressFn =
    std::function<void(int device, qint64 done, qint64 total, const QString& text)>;

struct LineBackupOptions {
    QString directory;        // created when missing
    QList<int> devices;       // empty: scan the line (0..63) first
    bool resume = false;      // skip devices the manifest has as saved and verified
    QString lineDescription;  // for the manifest: "/dev/ttyUSB0, multiuser, 38400 baud"
};

// "device-05_11.10.1994_32out.json": device number, EPROM date, outputs.
QString lineImageName(int device, const DeviceInfo& identity);

// Runs inside a worker job. The Error only when nothing could be done
// (folder not writable, scan failed, cancelled before the first device);
// otherwise the manifest, whose entries say per device what happened.
// `connection` is left addressed to the last device it reached: address
// it again (setDevice) before further work with one device.
Result<LineManifest> backupLine(comm::CamConDevice& connection, const LineBackupOptions& options,
                                const UseCaseProgress& progress = {},
                                const DeviceProgressFn& perDevice = {});

struct LineVerifyEntry {
    int device = 0;
    QString file;
    bool equal = false;
    QString text;  // "device 5: equals device-05_....json (42 blocks)" or what went wrong
};

// Compares every device the manifest lists as saved with its image (the
// image's SHA-256 is checked against the manifest first). Devices whose
// backup failed are listed as not verified. Addressing as backupLine.
Result<QList<LineVerifyEntry>> verifyLine(comm::CamConDevice& connection, const QString& directory,
                                          const UseCaseProgress& progress = {},
                                          const DeviceProgressFn& perDevice = {});

}  // namespace cambench::usecases
