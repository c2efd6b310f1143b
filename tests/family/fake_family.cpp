#include "fake_family.h"

#include "app/cli/cli_output.h"
#include "app/cli/commands.h"
#include "app/cli/exit_codes.h"
#include "comm/device/family_registry.h"
#include "comm/device/protocol_registry.h"
#include "comm/engine/request_engine.h"
#include "comm/sim/simulator_registry.h"
#include "ui/device_session.h"
#include "ui/family_gui.h"
#include "ui/main_window.h"
#include "ui/section_page.h"

#include <QAction>
#include <QLabel>
#include <QMenu>
#include <QPushButton>
#include <QVBoxLayout>

namespace cambench::fake {

namespace {

QAtomicInt g_requests;

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

// The simulated fake device: answers "ID?" and "PING n".
class FakeEndpoint : public comm::SimEndpoint {
public:
    QList<comm::SimOutput> receive(QByteArrayView bytes, qint64) override {
        QList<comm::SimOutput> replies;
        m_input += bytes.toByteArray();
        for (qsizetype end = m_input.indexOf('\n'); end >= 0; end = m_input.indexOf('\n')) {
            const QByteArray request = m_input.left(end);
            m_input.remove(0, end + 1);
            g_requests.fetchAndAddRelaxed(1);
            if (request == "ID?")
                replies << comm::SimOutput{"FAKE-1 simulated\n", 1};
            else if (request.startsWith("PING "))
                replies << comm::SimOutput{"PONG " + request.mid(5) + '\n', 1};
            else
                replies << comm::SimOutput{"ERR\n", 1};
        }
        return replies;
    }
    QString protocolName() const override { return QStringLiteral("fake line"); }

private:
    QByteArray m_input;
};

comm::SimulatedLine fakeLine(const comm::SerialSettings& serial) {
    return {std::make_unique<FakeEndpoint>(), comm::SimPacer(serial.baud, false),
            QStringLiteral("fake simulator")};
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
        connect(ping, &QPushButton::clicked, this, [this] {
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
// one screenshot-tour stop.
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
    QList<TourStop> tourStops(const QString&) override {
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

}  // namespace

struct FakeDevice::Impl {
    Impl(comm::Transport& transport, const comm::LineTiming& line)
        : engine(transport, backend, comm::EngineSettings{line, 1, 0}) {}
    LineBackend backend;
    comm::RequestEngine engine;
};

FakeDevice::FakeDevice(comm::Transport& transport, const comm::LineTiming& line)
    : d(std::make_unique<Impl>(transport, line)) {}

FakeDevice::~FakeDevice() = default;

comm::RequestEngine& FakeDevice::engine() {
    return d->engine;
}

Result<QString> FakeDevice::identify() {
    comm::Request request;
    request.label = QStringLiteral("ID?");
    request.message = "ID?";
    request.longestReplyBytes = 32;
    const Result<QByteArray> reply = d->engine.send(request);
    if (!reply) return reply.error();
    if (!reply->startsWith("FAKE"))
        return Error::communication(QStringLiteral("not a fake device"));
    return QString::fromLatin1(*reply);
}

Result<QString> FakeDevice::ping(int n) {
    comm::Request request;
    request.label = QStringLiteral("PING");
    request.message = "PING " + QByteArray::number(n);
    request.longestReplyBytes = 16;
    const Result<QByteArray> reply = d->engine.send(request);
    if (!reply) return reply.error();
    return QString::fromLatin1(*reply);
}

int requestsReceived() {
    return g_requests.loadRelaxed();
}

void registerFakeFamily() {
    comm::FamilyInfo family;
    family.id = QStringLiteral("fake");
    family.title = QStringLiteral("Fake test device");
    family.defaultProtocol = QStringLiteral("fake-line");
    family.built = true;
    comm::FamilyRegistry::instance().add(family);

    comm::ProtocolInfo protocol;
    protocol.id = QStringLiteral("fake-line");
    protocol.familyId = QStringLiteral("fake");
    protocol.title = QStringLiteral("Fake line protocol");
    protocol.makeSettings = [] { return std::make_unique<FakeSettings>(); };
    protocol.connect =
        [](comm::Transport& transport, const comm::ProtocolSettings&,
           const comm::LineTiming& line) -> Result<std::unique_ptr<comm::DeviceConnection>> {
        return std::unique_ptr<comm::DeviceConnection>(
            std::make_unique<FakeDevice>(transport, line));
    };
    comm::ProtocolRegistry::instance().add(protocol);

    comm::SimulatorRegistry::instance().add(
        {QStringLiteral("fake"),
         [](const QString&, const comm::SerialSettings& serial,
            const QString&) -> Result<comm::SimulatedLine> { return fakeLine(serial); },
         [] { return QList<QCommandLineOption>{}; },
         [](const QCommandLineParser&, const comm::SimHostOptions&) -> Result<comm::SimulatedLine> {
             return fakeLine({});
         }});

    static bool pagesAdded = false;
    if (!pagesAdded) {
        pagesAdded = true;
        FamilyGuiRegistry::instance().add(
            {QStringLiteral("fake"),
             [](DeviceSession* session, QObject* parent) { return new FakeGui(session, parent); }});
        cli::CommandRegistry::instance().add(
            {QStringLiteral("fake"), QStringLiteral("ping"), runPing});
        cli::CommandRegistry::instance().addHelp(QStringLiteral("fake"),
                                                 QStringLiteral("  ping N    answers PONG N\n"));
    }
}

}  // namespace cambench::fake
