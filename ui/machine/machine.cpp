#include "machine.h"

#include "machine_stop.h"
#include "machine_unit.h"
#include "machine_window.h"
#include "ui/program_stop.h"
#include "ui/window_fit.h"

#include "model/atomic_file.h"
#include "ui/device_session.h"
#include "ui/main_window.h"

namespace cambench {

Machine::Machine(const MachineFile& file, QString path, QObject* parent)
    : QObject(parent),
      m_name(file.machine),
      m_path(std::move(path)),
      m_shaftFrom(file.shaftFrom),
      m_shaftTo(file.shaftTo),
      m_stop(new MachineStop(this)) {
    // Escape from every window and dialog, every dialog's STOP: also this machine's.
    ProgramStop::instance().add(m_stop);
    for (const MachineDevice& device : file.devices) createUnit(device);
}

Machine::~Machine() {
    // The pages of the devices' windows point at the units.
    delete m_window;
    qDeleteAll(m_units);
}

MachineUnit* Machine::createUnit(const MachineDevice& device) {
    auto* unit = new MachineUnit(device, m_stop);
    m_units << unit;
    m_stop->addDevice(device.name, unit->session()->motionStop());
    connect(unit, &MachineUnit::languageRequested, this, &Machine::languageRequested);
    return unit;
}

MachineWindow* Machine::window() const {
    return m_window;
}

MachineUnit* Machine::unit(const QString& name) const {
    for (MachineUnit* unit : m_units)
        if (unit->name() == name) return unit;
    return nullptr;
}

MachineFile Machine::file() const {
    MachineFile file;
    file.machine = m_name;
    for (const MachineUnit* unit : m_units) file.devices << unit->device();
    file.shaftFrom = m_shaftFrom;
    file.shaftTo = m_shaftTo;
    return file;
}

void Machine::createWindow() {
    m_window = new MachineWindow(this);
    connect(m_window, &MachineWindow::closed, this, &Machine::closed);
}

void Machine::open() {
    createWindow();
    showFitting(*m_window, false);
    for (MachineUnit* unit : m_units) unit->connectDevice();
}

void Machine::rebuildWindow() {
    if (!m_window) return;
    MachineWindow* old = m_window;
    const QString current = old->currentDevice();
    createWindow();
    m_window->setGeometry(old->geometry());
    m_window->showDevice(current);
    m_window->show();
    // Now, not later: the switch comes through a queued call, and the
    // devices' windows it showed are the new one's now.
    delete old;
}

Result<MachineUnit*> Machine::addDevice(const MachineDevice& device) {
    if (unit(device.name))
        return Error::invalidData(
            tr("The machine has a device named \"%1\" already; give this one another name.")
                .arg(device.name));
    MachineUnit* added = createUnit(device);
    Q_EMIT deviceAdded(added);
    added->connectDevice();
    return added;
}

Status Machine::save(const QString& path) {
    const Status written = writeFileAtomically(path, machineFileJson(file()));
    if (written) m_path = path;
    return written;
}

}  // namespace cambench
