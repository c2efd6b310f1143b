#pragma once

#include "sim_axis.h"
#include "sim_cam_store.h"
#include "sim_eeprom.h"
#include "sim_profile.h"
#include "sim_result.h"
#include "sim_state.h"

#include "comm/sim/camcon/table/sim_table_state.h"

#include "comm/camcon/ascii/catalogue.h"
#include "comm/camcon/ascii/frame.h"

#include <QByteArray>
#include <QHash>

#include <optional>

namespace cambench::comm {

// What a device knows while it runs but does not keep in its EEPROM.
struct SimRuntime {
    static constexpr int kRamBytes = 4096;
    int errorState = 0;                            // ?ERR
    QHash<SimPlcKey, qint32> plcActuals;           // timer and counter actual values (?SPSIST)
    QByteArray vInputs;                            // !GVSPSTAB
    int userCursor = 0;                            // position of the ?USER00 / ?USER01 walk
    QByteArray ram = QByteArray(kRamBytes, '\0');  // ?ML / !MS / !MW
};

// One simulated CamCon: the state of the manual's menus, decoded with the
// command catalogue. Handlers live in files by manual section
// (sim_*_handlers.cpp) and register themselves in the constructor.
class SimDevice {
public:
    struct Reply {
        Frame frame;
        int delayMs = 0;
    };

    explicit SimDevice(SimProfile profile = {}, int number = 0);
    SimDevice(const SimDevice&) = delete;
    SimDevice& operator=(const SimDevice&) = delete;

    // Executes a request and answers it; nullopt when the device stays
    // silent (!GRESET). Counted in executions().
    std::optional<Reply> execute(const Frame& request);

    int number() const { return m_number; }
    const SimProfile& profile() const { return m_profile; }
    SimState& state() { return m_state; }
    const SimState& state() const { return m_state; }
    SimCamCursor& cursor() { return m_cursor; }
    SimEeprom& eeprom() { return m_eeprom; }
    SimAxis& axis() { return m_axis; }
    const SimAxis& axis() const { return m_axis; }
    SimRuntime& runtime() { return m_runtime; }
    SimTableState& tableState() { return m_tableState; }
    const SimTableState& tableState() const { return m_tableState; }

    // Runs the handler of one catalogue command directly, without a frame:
    // the table interface reaches the same state through it. nullopt when
    // the device has no handler for the command.
    std::optional<SimResult> call(char kind, const QByteArray& name, const Fields& fields = {});

    bool checksumsEnabled() const { return m_checksums; }
    void setChecksumsEnabled(bool enabled) { m_checksums = enabled; }
    qint64 executions() const { return m_executions; }

    // The state after !CA: no cams, default settings.
    void clearAll();
    // Replaces the state (EEPROM restore) and starts the device.
    void start(SimState state);
    // !EE0000: EEPROM erased, device stopped until the restore completes.
    void erase();

    void addHandler(char kind, const QByteArray& name, SimHandler handler);
    bool hasHandler(char kind, const QByteArray& name) const;
    // A firmware without this command: it answers :Z from now on (tests
    // of `check`: a device that disagrees with our catalogue).
    void forgetCommand(char kind, const QByteArray& name);

private:
    QByteArray replyBody(const CommandSpec& spec, const SimResult& result) const;

    SimProfile m_profile;
    int m_number;
    SimState m_state;
    SimCamCursor m_cursor;
    SimEeprom m_eeprom;
    SimAxis m_axis;
    SimRuntime m_runtime;
    SimTableState m_tableState;
    bool m_checksums = true;
    qint64 m_executions = 0;
    QHash<QByteArray, SimHandler> m_handlers;  // key: kind + name, e.g. "?NF"
};

}  // namespace cambench::comm
