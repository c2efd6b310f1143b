// The devices of a machine at once, one thread per port.
//
// Threads, not child processes of cambench-cli: a device's work already
// runs on its CommWorker's thread, and the CLI thread of a CliSession only
// runs an event loop until the result arrives, which it does as well on a
// thread of its own as on the main thread. The commands hold no mutable
// statics (the registries are filled before main's dispatch and only read
// afterwards), and everything they print passes through cli_output, which
// captures it per thread (CaptureOutput). Child processes would isolate
// more but cost a process start per device, a second way to pass each
// device's options and a JSON protocol back for its result.
#include "machine_parallel.h"

#include "cli_output.h"

#include <QEventLoop>
#include <QFileInfo>
#include <QMetaObject>
#include <QThread>

#include <memory>
#include <vector>

namespace cambench::cli {

namespace {

// Two devices on one port must never be asked at once: /dev/ttyUSB0 and
// its /dev/serial/by-id/ link are one port.
QString portKey(const GlobalOptions& options) {
    const QFileInfo file(options.port);
    return file.exists() ? file.canonicalFilePath() : options.port.toLower();
}

// `indices` grouped by port, each group in the order given, the groups in
// the order of their first device.
QList<QList<int>> groupsByPort(const QList<GlobalOptions>& options, const QList<int>& indices) {
    QStringList keys;
    QList<QList<int>> groups;
    for (int index : indices) {
        const QString key = portKey(options.at(index));
        const qsizetype at = keys.indexOf(key);
        if (at >= 0) {
            groups[at] << index;
        } else {
            keys << key;
            groups << QList<int>{index};
        }
    }
    return groups;
}

}  // namespace

void runDevicesByPort(const QList<GlobalOptions>& options, const QList<int>& indices,
                      const std::function<void(int)>& work, const std::function<void(int)>& done) {
    // One slot per device, each written by one thread only; the main thread
    // reads a slot after that device's queued notice, which orders the two.
    std::vector<OutputBlock> blocks(size_t(options.size()));
    std::vector<bool> finished(size_t(options.size()), false);
    qsizetype printed = 0;  // indices.at(printed) is the next block to print
    qsizetype open = indices.size();
    QEventLoop loop;
    QObject receiver;  // lives on this thread: the notices are run here
    const auto finish = [&](int index) {
        finished[size_t(index)] = true;
        if (done) done(index);
        while (printed < indices.size() && finished[size_t(indices.at(printed))])
            blocks[size_t(indices.at(printed++))].print();
        if (--open == 0) loop.quit();
    };
    std::vector<std::unique_ptr<QThread>> threads;
    for (const QList<int>& group : groupsByPort(options, indices)) {
        threads.emplace_back(QThread::create([&, group] {
            for (int index : group) {
                {
                    const CaptureOutput capture(blocks[size_t(index)]);
                    work(index);
                }
                QMetaObject::invokeMethod(
                    &receiver, [&finish, index] { finish(index); }, Qt::QueuedConnection);
            }
        }));
        threads.back()->start();
    }
    if (open > 0) loop.exec();
    for (const std::unique_ptr<QThread>& thread : threads) thread->wait();
}

}  // namespace cambench::cli
