#include "fake_family.h"
#include "fake_backup.h"

#include "app/cli/cli_output.h"
#include "app/cli/commands.h"
#include "app/cli/exit_codes.h"
#include "app/registry/family_parts.h"
#include "comm/device/family_registry.h"
#include "comm/device/protocol_registry.h"
#include "comm/engine/request_engine.h"
#include "comm/sim/simulator_registry.h"
#include "comm/usecases/device_check.h"
#include "ui/device_session.h"
#include "ui/family_gui.h"
#include "ui/main_window.h"
#include "ui/section_page.h"

#include <QAction>
#include <QLabel>
#include <QMap>
#include <QMenu>
#include <QPushButton>
#include <QRegularExpression>
#include <QSet>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <mutex>

namespace cambench::fake {

namespace {

QAtomicInt g_requests;
std::mutex g_logMutex;
QStringList g_log;

// A number the simulator's port names ("axes=2"), else `fallback`.
int portNumber(const QString& port, const QString& key, int fallback) {
    const QRegularExpressionMatch match =
        QRegularExpression(key + QStringLiteral("=(\\d+)")).match(port);
    return match.hasMatch() ? match.captured(1).toInt() : fallback;
}

// One text line per message, ended by '\n'.
class LineBackend : public comm::FramingBackend {
public:
    QString describe() const override { return QStringLiteral("fake line"); }
    QString checkHint() const override { return QStringLiteral("check the fake device"); }
    void beginRequest(const comm::Request&) override {}
    comm::BackendStep startAttempt(const comm::Request& request, int, qint64) override {
        comm::BackendStep step;
        step.write = request.message + '\n';
        step.sent = true;
        return step;
    }
    comm::BackendStep feed(QByteArrayView bytes, qint64) override {
        comm::BackendStep step;
        m_input += bytes.toByteArray();
        for (qsizetype end = m_input.indexOf('\n'); end >= 0; end = m_input.indexOf('\n')) {
            comm::Incoming line;
            line.message = m_input.left(end);
            line.wire = m_input.left(end + 1);
            m_input.remove(0, end + 1);
            step.incoming << line;
        }
        return step;
    }
    QByteArray resetInput() override { return std::exchange(m_input, {}); }
    qint64 requestWireBytes(const comm::Request& request) const override {
        return request.message.size() + 1;
    }
    qint64 replyWireBytes(const comm::Request& request) const override {
        return request.longestReplyBytes + 1;
    }

private:
    QByteArray m_input;
};

class FakeSettings : public comm::ProtocolSettings {
public:
    QString protocolId() const override { return QStringLiteral("fake-line"); }
    std::unique_ptr<comm::ProtocolSettings> clone() const override {
        return std::make_unique<FakeSettings>(*this);
    }
    QVariantMap toMap() const override { return {}; }
    void fromMap(const QVariantMap&) override {}
};

// The simulated fake device: answers "ID?" (with its number of axes),
// "PING n", "MOVE n", "STOP n" (not for its deaf axis) and "STATE?".
class FakeEndpoint : public comm::SimEndpoint {
public:
    FakeEndpoint(int axes, int deafAxis, int serial, int registers)
        : m_axes(axes), m_deafAxis(deafAxis), m_serial(serial) {
        for (int n = 1; n <= registers; ++n) m_registers.insert(n, serial * 100 + n);
    }
    QList<comm::SimOutput> receive(QByteArrayView bytes, qint64) override {
        QList<comm::SimOutput> replies;
        m_input += bytes.toByteArray();
        for (qsizetype end = m_input.indexOf('\n'); end >= 0; end = m_input.indexOf('\n')) {
            const QByteArray request = withoutNoise(m_input.left(end));
            m_input.remove(0, end + 1);
            g_requests.fetchAndAddRelaxed(1);
            {
                std::lock_guard lock(g_logMutex);
                g_log << QString::fromLatin1(request);
            }
            replies << comm::SimOutput{answer(request) + '\n', 1};
        }
        return replies;
    }
    QString protocolName() const override { return QStringLiteral("fake line"); }

private:
    // On a line others spoke on first (Detect's tries of other protocols),
    // what came before the device's own request is noise, as for a device
    // that waits for its command.
    static QByteArray withoutNoise(const QByteArray& line) {
        qsizetype from = 0;
        for (const char* start : {"ID?", "PING ", "MOVE ", "STOP ", "STATE?", "GET ", "SET "})
            from = std::max(from, line.lastIndexOf(start));
        return line.mid(from);
    }
    QByteArray answer(const QByteArray& request) {
        const int axis = request.mid(request.indexOf(' ') + 1).toInt();
        const bool known = axis >= 1 && axis <= m_axes;
        if (request == "ID?")
            return "FAKE-1 simulated axes=" + QByteArray::number(m_axes) +
                   " serial=" + QByteArray::number(m_serial) +
                   " regs=" + QByteArray::number(m_registers.size());
        if (request.startsWith("GET ") && m_registers.contains(axis))
            return "VAL " + QByteArray::number(axis) + ' ' +
                   QByteArray::number(m_registers.value(axis));
        if (request.startsWith("SET ")) {
            const QList<QByteArray> fields = request.split(' ');
            bool ok = fields.size() == 3;
            const int n = ok ? fields.at(1).toInt() : 0;
            const int value = ok ? fields.at(2).toInt(&ok) : 0;
            if (!ok || !m_registers.contains(n)) return "ERR";
            m_registers.insert(n, value);
            return "VAL " + QByteArray::number(n) + ' ' + QByteArray::number(value);
        }
        if (request.startsWith("PING ")) return "PONG " + request.mid(5);
        if (request.startsWith("MOVE ") && known) {
            m_moving.insert(axis);
            return "MOVING " + QByteArray::number(axis);
        }
        if (request.startsWith("STOP ") && known && axis != m_deafAxis) {
            m_moving.remove(axis);
            return "STOPPED " + QByteArray::number(axis);
        }
        if (request == "STATE?") {
            QList<int> moving = m_moving.values();
            std::sort(moving.begin(), moving.end());
            QByteArray state = "STATE";
            for (int a : moving) state += ' ' + QByteArray::number(a);
            return state;
        }
        return "ERR";
    }

    QByteArray m_input;
    int m_axes;
    int m_deafAxis;
    int m_serial;
    QMap<int, qint32> m_registers;
    QSet<int> m_moving;
};

comm::SimulatedLine fakeLine(const QString& port, const comm::SerialSettings& serial) {
    return {std::make_unique<FakeEndpoint>(portNumber(port, QStringLiteral("axes"), 1),
                                           portNumber(port, QStringLiteral("deaf"), 0),
                                           portNumber(port, QStringLiteral("serial"), 1),
                                           portNumber(port, QStringLiteral("regs"), 4)),
            comm::SimPacer(serial.baud, false), QStringLiteral("fake simulator")};
}

// The family's one page: a button that pings the device.
class FakePage : public SectionPage {
public:
    explicit FakePage(DeviceSession* session) : m_session(session) {
        setObjectName(QStringLiteral("fakePage"));
        auto* layout = new QVBoxLayout(this);
        auto* ping = new QPushButton(QStringLiteral("Ping"));
        ping->setObjectName(QStringLiteral("fakePing"));
        m_answer = new QLabel;
        m_answer->setObjectName(QStringLiteral("fakeAnswer"));
        layout->addWidget(ping);
        layout->addWidget(m_answer);
        // Widgets that take Escape for themselves: the STOP key must work
        // from them too.
        auto* number = new QSpinBox;
        number->setObjectName(QStringLiteral("fakeNumber"));
        auto* table = new QTableWidget(2, 2);
        table->setObjectName(QStringLiteral("fakeTable"));
        layout->addWidget(number);
        layout->addWidget(table);
        connect(ping, &QPushButton::clicked, this, [this] {
            // "…" while it runs: the shell takes it away when the job is done.
            Q_EMIT statusMessage(QStringLiteral("Pinging the fake device…"));
            m_session->worker().run<Result<QString>>(
                this, comm::JobPriority::User, QStringLiteral("ping"),
                [](comm::JobContext& job) -> Result<QString> {
                    Result<FakeDevice*> device = job.family<FakeDevice>();
                    if (!device) return device.error();
                    return (*device)->ping(7);
                },
                [this](Result<QString> answer) {
                    m_answer->setText(answer ? *answer : answer.error().message);
                });
        });
    }
    QString sectionTitle() const override { return QStringLiteral("Fake device"); }

private:
    DeviceSession* m_session;
    QLabel* m_answer;
};

// The family's part of the window: its page, one Device menu entry and
// screenshot-tour visits (one never reached) with one stop each.
class FakeWindow : public FamilyWindow {
public:
    FakeWindow(FamilyGui* gui, MainWindow* window)
        : FamilyWindow(gui, window), m_page(new FakePage(gui->session())) {}
    QList<SectionPage*> pages() const override { return {m_page}; }
    void addMenuEntries(const FamilyMenus& menus) override {
        QAction* ping = menus.device->addAction(QStringLiteral("Ping the fake device"), this,
                                                [this] { window()->showPage(m_page); });
        ping->setObjectName(QStringLiteral("fakePingAction"));
    }
    QList<TourVisit> tourVisits() const override {
        // The second is never reached: the tour must say so.
        return {
            {QStringLiteral("fake"), QStringLiteral("sim:throttle=0"), QStringLiteral("fake-line")},
            {QStringLiteral("fake-unreachable"), QStringLiteral("/dev/cambench-no-such-port"),
             QStringLiteral("fake-line")}};
    }
    QList<TourStop> tourStops(const TourVisit&, const QString&) override {
        return {{QStringLiteral("01-fake"),
                 [this] { window()->showPage(m_page); },
                 [] { return true; },
                 {}}};
    }

private:
    FakePage* m_page;
};

class FakeGui : public FamilyGui {
public:
    FakeGui(DeviceSession* session, QObject* parent)
        : FamilyGui(QStringLiteral("fake"), session, parent) {}
    FamilyWindow* createWindow(MainWindow* window) override { return new FakeWindow(this, window); }
};

// cambench-cli --family fake ping N
int runPing(cli::CliSession& session, cli::CommandArgs& args) {
    const Result<int> n = cli::parseIntArgument(args.takePositional(), QStringLiteral("N"), 0, 99);
    if (!n) return cli::reportError(n.error());
    if (const Status done = args.finish(); !done) return cli::reportError(done.error());
    const Result<QString> answer = session.run<FakeDevice, QString>(
        QStringLiteral("ping"),
        [n = *n](FakeDevice& device, comm::JobContext&) { return device.ping(n); });
    if (!answer) return cli::reportError(answer.error());
    cli::printOut(*answer + QLatin1Char('\n'));
    return cli::ExitOk;
}

// The family's check: only its identity query goes out.
QString refusesAllButIdentity(const QString&, const comm::Request& request) {
    return request.message == "ID?" ? QString() : QStringLiteral("only ID? reads");
}

Result<QList<usecases::CheckResult>> checkIdentity(comm::DeviceConnection& connection,
                                                   const usecases::UseCaseProgress&) {
    const Result<QString> identity = connection.identify();
    usecases::CheckResult result;
    result.id = QStringLiteral("fake.id");
    result.reading = QStringLiteral("ID? answers FAKE-1");
    result.source = QStringLiteral("tests/family/fake_family.cpp");
    result.verdict = identity ? usecases::CheckVerdict::Held : usecases::CheckVerdict::CouldNotTell;
    result.observed = identity ? QString() : identity.error().message;
    return QList<usecases::CheckResult>{result};
}

}  // namespace

struct FakeDevice::Impl {
    Impl(comm::Transport& transport, const comm::LineTiming& line)
        : engine(transport, backend, comm::EngineSettings{line, 1, 0}) {}
    Result<QByteArray> ask(const QByteArray& message,
                           comm::RetryPolicy retry = comm::RetryPolicy::Idempotent);
    LineBackend backend;
    comm::RequestEngine engine;
    // "VAL n v" -> v.
    Result<qint32> registerValue(const QByteArray& message, int n);
    int axes = 0;  // from the identity; 0 until identified
    int serial = 0;
    int registers = 0;
};

FakeDevice::FakeDevice(comm::Transport& transport, const comm::LineTiming& line)
    : d(std::make_unique<Impl>(transport, line)) {}

FakeDevice::~FakeDevice() = default;

comm::RequestEngine& FakeDevice::engine() {
    return d->engine;
}

Result<QByteArray> FakeDevice::Impl::ask(const QByteArray& message, comm::RetryPolicy retry) {
    comm::Request request;
    request.label = QString::fromLatin1(message.left(message.indexOf(' ')));
    request.message = message;
    request.longestReplyBytes = 40;
    request.retry = retry;
    return engine.send(request);
}

Result<QString> FakeDevice::identify() {
    const Result<QByteArray> reply = d->ask("ID?");
    if (!reply) return reply.error();
    if (!reply->startsWith("FAKE"))
        return Error::communication(QStringLiteral("not a fake device"));
    const QString text = QString::fromLatin1(*reply);
    d->axes = portNumber(text, QStringLiteral("axes"), 1);
    d->serial = portNumber(text, QStringLiteral("serial"), 0);
    d->registers = portNumber(text, QStringLiteral("regs"), 0);
    return text;
}

DeviceIdentity FakeDevice::identity() const {
    DeviceIdentity identity;
    if (d->serial > 0) identity.set(QStringLiteral("serial"), QString::number(d->serial));
    return identity;
}

Result<DeviceIdentity> FakeDevice::readIdentity() {
    if (const Result<QString> text = identify(); !text) return text.error();
    return identity();
}

int FakeDevice::registers() const {
    return d->registers;
}

Result<qint32> FakeDevice::Impl::registerValue(const QByteArray& message, int n) {
    const Result<QByteArray> reply = ask(message);
    if (!reply) return reply.error();
    const QList<QByteArray> fields = reply->split(' ');
    bool ok = fields.size() == 3 && fields.at(0) == "VAL" && fields.at(1).toInt() == n;
    const qint32 value = ok ? fields.at(2).toInt(&ok) : 0;
    if (!ok)
        return Error::communication(QStringLiteral("register %1: the fake device answered \"%2\"")
                                        .arg(n)
                                        .arg(QString::fromLatin1(*reply)));
    return value;
}

Result<qint32> FakeDevice::readRegister(int n) {
    return d->registerValue("GET " + QByteArray::number(n), n);
}

Result<qint32> FakeDevice::writeRegister(int n, qint32 value) {
    return d->registerValue("SET " + QByteArray::number(n) + ' ' + QByteArray::number(value), n);
}

Result<QString> FakeDevice::ping(int n) {
    const Result<QByteArray> reply = d->ask("PING " + QByteArray::number(n));
    if (!reply) return reply.error();
    return QString::fromLatin1(*reply);
}

Result<QString> FakeDevice::move(int axis) {
    const Result<QByteArray> reply =
        d->ask("MOVE " + QByteArray::number(axis), comm::RetryPolicy::Never);
    if (!reply) return reply.error();
    if (*reply == "ERR") return Error::communication(QStringLiteral("move refused"));
    return QString::fromLatin1(*reply);
}

comm::MotionStopReport FakeDevice::stopAllMotion() {
    if (d->axes == 0) identify();  // the shell asks after identify(); a job may not have
    comm::MotionStopReport report;
    for (int axis = 1; axis <= std::max(d->axes, 1); ++axis) {
        const Result<QByteArray> reply = d->ask("STOP " + QByteArray::number(axis));
        const bool acknowledged = reply && reply->startsWith("STOPPED");
        report.lines << comm::MotionStopLine{
            QStringLiteral("Axis %1").arg(axis), acknowledged,
            reply ? (acknowledged ? QString() : QStringLiteral("refused")) : reply.error().message};
    }
    return report;
}

Result<QStringList> FakeDevice::activeMotion() {
    const Result<QByteArray> reply = d->ask("STATE?");
    if (!reply) return reply.error();
    if (!reply->startsWith("STATE")) return Error::communication(QStringLiteral("no state"));
    QStringList moving;
    for (const QByteArray& axis : reply->mid(5).trimmed().split(' '))
        if (!axis.isEmpty())
            moving << QStringLiteral("axis %1 moves").arg(QString::fromLatin1(axis));
    return moving;
}

int requestsReceived() {
    return g_requests.loadRelaxed();
}

QStringList requestLog() {
    std::lock_guard lock(g_logMutex);
    return g_log;
}

void clearRequestLog() {
    std::lock_guard lock(g_logMutex);
    g_log.clear();
}

comm::FamilyInfo builtTestFamily(const QString& title, const QString& defaultProtocol) {
    comm::FamilyInfo family;
    family.title = title;
    family.defaultProtocol = defaultProtocol;
    family.built = true;
    return family;
}

comm::ProtocolInfo fakeLineProtocol(const QString& id, const QString& title) {
    comm::ProtocolInfo protocol;
    protocol.id = id;
    protocol.title = title;
    protocol.makeSettings = [] { return std::make_unique<FakeSettings>(); };
    protocol.connect =
        [](comm::Transport& transport, const comm::ProtocolSettings&,
           const comm::LineTiming& line) -> Result<std::unique_ptr<comm::DeviceConnection>> {
        return std::unique_ptr<comm::DeviceConnection>(
            std::make_unique<FakeDevice>(transport, line));
    };
    return protocol;
}

// Every part of the family, named in one place as a built-in family's are
// (app/registry/<family>/<family>_parts.cpp), and registered the same way.
FamilyParts fakeParts() {
    FamilyParts parts;
    parts.id = QStringLiteral("fake");
    parts.family = [] {
        return builtTestFamily(QStringLiteral("Fake test device"), QStringLiteral("fake-line"));
    };
    parts.protocols = [] {
        return QList{
            fakeLineProtocol(QStringLiteral("fake-line"), QStringLiteral("Fake line protocol"))};
    };
    parts.simulator = [] {
        comm::SimulatorInfo simulator;
        simulator.fromPort = [](const QString& port, const comm::SerialSettings& serial,
                                const QString&) -> Result<comm::SimulatedLine> {
            return fakeLine(port, serial);
        };
        simulator.options = [] { return QList<QCommandLineOption>{}; };
        simulator.fromOptions = [](const QCommandLineParser&,
                                   const comm::SimHostOptions&) -> Result<comm::SimulatedLine> {
            return fakeLine({}, {});
        };
        return simulator;
    };
    parts.checks = [] {
        usecases::FamilyCheck check;
        check.refuses = refusesAllButIdentity;
        check.run = checkIdentity;
        return check;
    };
    parts.backup = fakeBackup;
    parts.gui = [](const QString& familyId) {
        FamilyGuiRegistry::instance().add({familyId, [](DeviceSession* session, QObject* parent) {
                                               return new FakeGui(session, parent);
                                           }});
    };
    parts.cli = [](const QString& familyId) {
        cli::FamilyCommands commands(cli::CommandRegistry::instance(), familyId);
        commands.add(QStringLiteral("ping"), runPing);
        commands.addHelp(QStringLiteral("  ping N    answers PONG N\n"));
    };
    return parts;
}

void registerFakeFamily() {
    registerFamily(fakeParts());
}

}  // namespace cambench::fake
