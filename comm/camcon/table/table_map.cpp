#include "table_map.h"

#include <QString>

#include <algorithm>

namespace cambench::comm::table {

namespace {

constexpr TableAccess R = TableAccess::Read;
constexpr TableAccess W = TableAccess::Write;
constexpr TableAccess RW = TableAccess::ReadWrite;

constexpr const char* kBits = "bit mask, bit 0 = lowest number";

// Manual chapter 3, area by area. Columns: first area, last area, first
// word, count, stride, access, key, meaning, unit, provisional reason.
// Words the manual lists as free or reserve are absent; so are area 201
// word 67 (actual-value simulation, "only on the PC Digisoft", no access
// given) and the areas 215, 217..223 (assignment "upon request").
const TableEntry kEntries[] = {
    // 3.1 Areas 1..200: cams and dead times of output n (= area n), in the
    // programming program (area 201 word 70).
    {1, 200, 0, 1, 1, RW, "track.dead_time", "Dead time of the output in dead-time mode 0 (normal)",
     "0.1 ms", nullptr},
    {1, 200, 1, 125, 2, RW, "track.cam_on",
     "Switch-on point of cam 1..125; an empty cam reads 0x80000000", "actual-value units", nullptr},
    {1, 200, 2, 125, 2, RW, "track.cam_off",
     "Switch-off point of cam 1..125; an empty cam reads 0x80000000", "actual-value units",
     nullptr},
    {1, 200, 251, 1, 1, RW, "track.dead_time_mode",
     "Dead-time mode: 0 normal (same for on and off), 1 separate on/off, 2 path-time cam", "",
     nullptr},
    {1, 200, 252, 1, 1, RW, "track.dead_time_on",
     "Dead time for the switch-on point (0..largest possible dead time)", "0.1 ms", nullptr},
    {1, 200, 253, 1, 1, RW, "track.dead_time_off",
     "Dead time for the switch-off point, or the switching time in mode 2", "0.1 ms",
     "the unit of the mode-2 switching time is not stated; 0.1 ms assumed"},
    {1, 200, 254, 1, 1, RW, "track.cam_count",
     "Read: number of cams on the track. Write: shifts every cam of the track by the value "
     "written (- or +)",
     "", nullptr},

    // 3.2 Area 201: status, actual value, program.
    {201, 201, 0, 1, 1, RW, "status.actual_value",
     "Actual value; writing sets it (and acknowledges e.g. a Hiperface clear)",
     "actual-value units", nullptr},
    {201, 201, 1, 1, 1, R, "status.speed", "Speed", "", nullptr},
    {201, 201, 2, 1, 1, RW, "status.program", "Active program; writing changes the program", "",
     nullptr},
    {201, 201, 3, 14, 1, R, "status.analog_output", "Value of analogue output 1..14",
     "scaled to 16 bits", nullptr},
    {201, 201, 17, 1, 1, R, "status.plc_boost", "PLC-BOOST: 0 absent, 1 present", "", nullptr},
    {201, 201, 18, 1, 1, R, "status.cpu_frequency",
     "CPU frequency: 0 = 16.7 MHz, 1 = 25.2 MHz (CPU type 0 only)", "", nullptr},
    {201, 201, 19, 1, 1, R, "status.temperature", "Temperature; 0xFF = no probe", "°C", nullptr},
    {201, 201, 20, 1, 1, R, "status.free_cams", "Number of free cams", "", nullptr},
    {201, 201, 21, 1, 1, R, "status.programmed_cams", "Number of programmed cams", "", nullptr},
    {201, 201, 22, 1, 1, R, "status.max_dead_time", "Largest possible dead time", "100 µs",
     nullptr},
    {201, 201, 23, 1, 1, R, "status.ram_size", "Total RAM size", "", nullptr},
    {201, 201, 24, 1, 1, R, "status.free_ram", "Free RAM", "", nullptr},
    {201, 201, 25, 1, 1, R, "status.serial_eeprom_size", "Size of the serial EEPROM", "", nullptr},
    {201, 201, 26, 1, 1, R, "status.parallel_eeprom_size", "Size of the parallel EEPROM", "",
     nullptr},
    {201, 201, 27, 1, 1, R, "status.min_actual_value", "Smallest possible actual value",
     "actual-value units", nullptr},
    {201, 201, 28, 1, 1, R, "status.max_actual_value", "Largest possible actual value",
     "actual-value units", nullptr},
    {201, 201, 29, 1, 1, R, "status.max_program", "Largest possible program number", "", nullptr},
    {201, 201, 30, 1, 1, R, "status.programmed_dead_times", "Number of programmed dead times", "",
     nullptr},
    {201, 201, 31, 3, 1, R, "status.eprom_date",
     "EPROM date, ASCII, 4 characters per word (11 in all)", "",
     "character order within a word not stated; first character in the high byte assumed"},
    {201, 201, 34, 1, 1, R, "status.device_status",
     "Device status: 0 OK, 1-3 actual-value error 1-3, 4 output error, 5 actual-value error 5, "
     "6 EEPROM overload by writing, 8 RAM too small (stopped), 0xFF EEPROM error; bit 8 data "
     "transfer running, bit 9 device cannot start",
     "", nullptr},
    {201, 201, 35, 1, 1, R, "status.eeprom_write_count",
     "EEPROM write counter; above 1 million data may be lost", "", nullptr},
    {201, 201, 36, 1, 1, R, "status.cpu_type", "CPU type: 0 = 68332, 1 = Coldfire, 2 = XScale", "",
     nullptr},
    {201, 201, 37, 1, 1, R, "status.cycle_time", "Current cycle time", "µs", nullptr},
    {201, 201, 38, 1, 1, R, "status.nlt_tables_used",
     "Number of NLT tables (non-linear dead times) in use", "", nullptr},
    {201, 201, 39, 1, 1, R, "status.status2",
     "Status 2, extended error display (e.g. EtherCAT error on a DC190)", "", nullptr},
    {201, 201, 40, 14, 1, R, "status.analog_input", "Value of analogue input 1..14",
     "scaled to 16 bits", nullptr},
    {201, 201, 66, 1, 1, R, "status.device_type", "CamCon type, e.g. 190 = DC190", "", nullptr},
    {201, 201, 68, 1, 1, R, "status.plc_timers_used",
     "Timers and counters used in the PLC logic module", "", nullptr},
    {201, 201, 69, 1, 1, R, "status.plc_shift_registers_used",
     "Shift registers used in the PLC logic module", "", nullptr},
    {201, 201, 70, 1, 1, RW, "status.programming_program",
     "Program whose cams areas 1..200 read and write (0..32767); write -1 to select the active "
     "program",
     "", nullptr},
    {201, 201, 71, 1, 1, RW, "status.copy_program",
     "Read: the programming program. Write: copies the programming program to the program "
     "written; with bit 31 set, the program written is deleted instead",
     "", "the manual's sentence on bit 31 is garbled; read as copy, or delete with bit 31"},
    {201, 201, 72, 1, 1, RW, "status.programming_select_mode",
     "Program selection mode of the programming program: 0 slow, 1 direct, 2 at the actual "
     "value",
     "", nullptr},
    {201, 201, 73, 1, 1, RW, "status.programming_switch_value",
     "Actual value at which the program changes in selection mode 2", "actual-value units",
     nullptr},

    // 3.3 Area 202: inputs, outputs, flags; 32 per word. Words 16 on need
    // the PLC logic module.
    {202, 202, 0, 7, 1, R, "io.outputs", "Hardware outputs O1..O200", kBits, nullptr},
    {202, 202, 8, 7, 1, R, "io.inputs", "Hardware inputs I1..I200", kBits, nullptr},
    {202, 202, 16, 7, 1, R, "io.plc_outputs_n", "Cam outputs N1..N200 (PLC module)", kBits,
     nullptr},
    {202, 202, 24, 8, 1, R, "io.plc_inputs_p", "Cam inputs P1..P256 (PLC module)", kBits, nullptr},
    {202, 202, 32, 8, 1, R, "io.plc_flags_m", "Flags M1..M256", kBits, nullptr},
    {202, 202, 40, 8, 1, R, "io.plc_flags_x", "Flags X1..X256", kBits, nullptr},
    {202, 202, 48, 8, 1, RW, "io.virtual_inputs",
     "Virtual inputs V1..V256; a DC300 or 1756-DICAM overwrites some from its backplane", kBits,
     nullptr},
    {202, 202, 56, 8, 1, R, "io.special_inputs", "Special inputs S1..S256", kBits, nullptr},
    {202, 202, 136, 23, 1, R, "io.plc_inputs_p_ext", "Cam inputs P257..P992", kBits, nullptr},
    {202, 202, 160, 23, 1, R, "io.plc_flags_m_ext", "Flags M257..M992", kBits, nullptr},
    {202, 202, 184, 23, 1, R, "io.plc_flags_x_ext", "Flags X257..X992", kBits, nullptr},
    {202, 202, 208, 23, 1, RW, "io.virtual_inputs_ext", "Virtual inputs V257..V992", kBits,
     nullptr},
    {202, 202, 232, 23, 1, R, "io.special_inputs_ext", "Special inputs S257..S992", kBits, nullptr},

    // 3.4 Area 203: system parameters. Writing any of them restarts the
    // device: only at standstill.
    {203, 203, 0, 1, 1, RW, "system.encoder_type",
     "Encoder: 0..20 SSI types (manual 3.4.1), -1 special encoder on the 1st SSI, 0xBFFFFFFF on "
     "the 2nd SSI (DC190); bit 30 selects interface B (DC190)",
     "", nullptr},
    {203, 203, 1, 1, 1, RW, "system.special_encoder_type",
     "Special encoder type (findSpecialEncoderLayout); write words 0..7 as one block", "", nullptr},
    {203, 203, 2, 6, 1, RW, "system.special_encoder_parameter",
     "Special encoder parameter 1..6; meaning depends on word 1", "", nullptr},
    {203, 203, 8, 1, 1, RW, "system.actual_value_hysteresis",
     "Hysteresis of the actual value (0..125, 0 = off)", "increments", nullptr},
    {203, 203, 9, 1, 1, RW, "system.v_max",
     "Largest change per cycle for encoder monitoring (0..9999)", "increments per cycle", nullptr},
    {203, 203, 10, 1, 1, RW, "system.gear_multiplier", "Gear multiplier (-99999..99999)", "",
     nullptr},
    {203, 203, 11, 1, 1, RW, "system.gear_divisor", "Gear divisor (1..99999)", "", nullptr},
    {203, 203, 12, 1, 1, RW, "system.axis_type", "Axis type: 0 rotary, 1 linear", "", nullptr},
    {203, 203, 13, 1, 1, RW, "system.linear_start_value", "Start value of a linear axis",
     "actual-value units", nullptr},
    {203, 203, 14, 1, 1, RW, "system.encoder_offset", "Zero offset of the encoder",
     "actual-value units", nullptr},
    {203, 203, 15, 1, 1, RW, "system.preset_value", "Preset value", "actual-value units", nullptr},
    {203, 203, 16, 1, 1, RW, "system.preset_input", "Preset input (0..200)", "", nullptr},
    {203, 203, 17, 1, 1, RW, "system.preset_retentive",
     "Preset kept over power-off: 0 no (RAM), 1 yes (EEPROM)", "", nullptr},
    {203, 203, 18, 1, 1, RW, "system.speed_factor", "Speed factor (1..9999999)", "", nullptr},
    {203, 203, 19, 1, 1, RW, "system.speed_100_percent", "Speed value for 100 % (1..10000)", "",
     nullptr},
    {203, 203, 20, 1, 1, RW, "system.speed_accuracy", "Speed accuracy (1..999)", "", nullptr},
    {203, 203, 21, 1, 1, RW, "system.display_mode", "Display: 0 auto, 1 speed, 2 position", "",
     nullptr},
    {203, 203, 22, 1, 1, RW, "system.display_switch_input",
     "Input that switches the display (0..200)", "", nullptr},
    {203, 203, 23, 1, 1, RW, "system.cable_length", "Encoder cable length (0..1000)", "m", nullptr},
    {203, 203, 24, 1, 1, RW, "system.cycle_time_target", "Target cycle time", "µs", nullptr},
    {203, 203, 25, 1, 1, RW, "system.safety_output", "Safety output (0..200)", "", nullptr},
    {203, 203, 26, 1, 1, RW, "system.actual_value_output",
     "Actual-value output: 0 off, 1 Gray, 2 binary, 3 external", "", nullptr},
    {203, 203, 27, 1, 1, RW, "system.direction_output", "Direction output (0..200)", "", nullptr},
    {203, 203, 28, 1, 1, RW, "system.standstill_output", "Standstill output (0..200)", "", nullptr},
    {203, 203, 29, 1, 1, RW, "system.speed_hysteresis", "Speed hysteresis (1..10000)", "", nullptr},
    {203, 203, 30, 1, 1, RW, "system.cam_inputs", "Number of cam controller inputs P (0..200)", "",
     nullptr},
    {203, 203, 31, 1, 1, RW, "system.cam_outputs", "Number of cam controller outputs N (0..200)",
     "", nullptr},
    {203, 203, 32, 1, 1, RW, "system.dead_time_outputs",
     "Number of outputs with dead-time compensation (0..200)", "", nullptr},
    {203, 203, 33, 1, 1, RW, "system.keypad_lock_input", "Keypad lock input (0..200)", "", nullptr},
    {203, 203, 34, 1, 1, RW, "system.program_select_inputs",
     "Number of inputs for external program selection (0..16)", "", nullptr},
    {203, 203, 35, 1, 1, RW, "system.program_select_first_input",
     "First input for external program selection (0..200)", "", nullptr},
    {203, 203, 36, 1, 1, RW, "system.program_select_mode",
     "Program selection: 0 slow, 1 direct, 2 at the actual value", "", nullptr},
    {203, 203, 37, 1, 1, RW, "system.program_select_value",
     "Actual value of program selection mode 2", "actual-value units", nullptr},
    {203, 203, 38, 1, 1, RW, "system.analog_outputs", "Number of analogue outputs (0..14)", "",
     nullptr},
    {203, 203, 39, 1, 1, RW, "system.analog_speed_output", "Analogue speed output: 0 no, 1 yes", "",
     nullptr},
    {203, 203, 40, 1, 1, RW, "system.internal_analog_outputs",
     "Number of internal analogue outputs (0..2; DC40 and DC51 only)", "", nullptr},
    {203, 203, 41, 2, 1, RW, "system.internal_analog_offset",
     "Offset of internal analogue output 1..2 (DC40 and DC51 only)", "", nullptr},
    {203, 203, 43, 2, 1, RW, "system.internal_analog_factor",
     "Factor of internal analogue output 1..2 (DC40 and DC51 only)", "", nullptr},
    {203, 203, 45, 1, 1, RW, "system.plc_module", "PLC logic module: 0 off, 1 on, 2 on, retentive",
     "", nullptr},
    {203, 203, 46, 1, 1, RW, "system.hardware_inputs",
     "Number of hardware inputs I (0..200; with a CP16 including its inputs)", "", nullptr},
    {203, 203, 47, 1, 1, RW, "system.hardware_outputs",
     "Number of hardware outputs O (8..200; with a CP16 including its outputs)", "", nullptr},
    {203, 203, 48, 1, 1, RW, "system.plc_flags_m", "Number of PLC flags M (0..248)", "", nullptr},
    {203, 203, 49, 1, 1, RW, "system.plc_flags_x", "Number of PLC flags X (0..248)", "", nullptr},
    {203, 203, 50, 1, 1, RW, "system.plc_timers_counters",
     "Number of PLC timers and counters (0..200)", "", nullptr},
    {203, 203, 51, 1, 1, RW, "system.plc_virtual_inputs", "Number of PLC virtual inputs V (0..200)",
     "", nullptr},
    {203, 203, 52, 1, 1, RW, "system.plc_special_inputs", "Number of PLC special inputs S (0..96)",
     "", nullptr},
    {203, 203, 53, 1, 1, RW, "system.master_program_on", "Master program: 0 off, 1 on", "",
     nullptr},
    {203, 203, 54, 1, 1, RW, "system.master_program", "Master program number (0..32767)", "",
     nullptr},
    {203, 203, 55, 8, 1, RW, "system.master_program_outputs",
     "Outputs 1..256 taken from the master program, 32 per word (bit set = master output)", kBits,
     nullptr},
    {203, 203, 63, 1, 1, RW, "system.dc300_mode", "DC300 mode: process alarm 0 off, 1 on", "",
     nullptr},
    {203, 203, 64, 1, 1, RW, "system.plc_shift_registers",
     "Number of shift registers in the PLC logic module (0..200)", "", nullptr},
    {203, 203, 65, 1, 1, RW, "system.plc_shift_register_length",
     "Longest shift register in the PLC logic module (0..999999)", "steps", nullptr},
    {203, 203, 66, 1, 1, RW, "system.output_enable_input",
     "Input that enables the cam outputs (0..200; devices without PLC link or logic module)", "",
     nullptr},
    {203, 203, 67, 1, 1, RW, "system.error_ack_input", "Input that acknowledges errors", "",
     nullptr},
    {203, 203, 68, 1, 1, RW, "system.nlt_tables",
     "Number of possible NLT tables (non-linear dead times)", "", nullptr},
    {203, 203, 69, 1, 1, RW, "system.standstill_hysteresis",
     "Hysteresis of the V<>0 (standstill) output", "%", nullptr},

    // 3.5 Area 204: 7 words per analogue cam output 1..14.
    {204, 204, 0, 14, 7, RW, "analog_out.min", "Smallest analogue value of output 1..14", "",
     nullptr},
    {204, 204, 1, 14, 7, RW, "analog_out.max", "Largest analogue value of output 1..14", "",
     nullptr},
    {204, 204, 2, 14, 7, RW, "analog_out.interpolation",
     "Interpolation of analogue output 1..14: 0 off, 1 on", "", nullptr},
    {204, 204, 3, 14, 7, RW, "analog_out.disable_input",
     "Input that disables the analogue cams of output 1..14 (0..200)", "", nullptr},
    {204, 204, 4, 14, 7, RW, "analog_out.disable_value",
     "Value of analogue output 1..14 while disabled", "", nullptr},
    {204, 204, 5, 14, 7, RW, "analog_out.gain", "Gain of analogue output 1..14", "", nullptr},
    {204, 204, 6, 14, 7, RW, "analog_out.offset", "Offset of analogue output 1..14",
     "16 bit, signed", nullptr},

    // 3.6 Area 205: device configuration.
    {205, 205, 0, 1, 1, RW, "config.device_number",
     "Device number for the serial interface (0..63)", "", nullptr},
    {205, 205, 1, 1, 1, W, "config.clear_all",
     "Write -1 to delete the whole memory of the device (programs and settings)", "", nullptr},
    {205, 205, 2, 1, 1, W, "config.hardware_reset",
     "Write -1 to restart the device; this write is not acknowledged", "", nullptr},
    {205, 205, 3, 1, 1, W, "config.error_ack",
     "Write -1 to try to acknowledge a pending actual-value or output error", "", nullptr},
    {205, 205, 4, 1, 1, RW, "config.eeprom_lock",
     "EEPROM lock: 0 unlocked, 1 locked (later writes go to RAM only and are lost at power-off; "
     "lock before cyclic writes; a complete deletion clears it)",
     "", nullptr},
    {205, 205, 5, 1, 1, RW, "config.hardware_inputs",
     "Number of hardware inputs without CP16 "
     "(0..200)",
     "", nullptr},
    {205, 205, 6, 1, 1, RW, "config.hardware_outputs",
     "Number of hardware outputs without CP16 (8..200)", "", nullptr},
    {205, 205, 7, 1, 1, RW, "config.cp_type", "CP or bus type: 0 none, 1 CP16/P/IO", "", nullptr},
    {205, 205, 8, 1, 1, RW, "config.profibus_address",
     "Profibus DP address with CP type 1; used after the next power-up", "", nullptr},
    {205, 205, 9, 1, 1, RW, "config.cp16_inputs", "Inputs simulated by the CP16 (CP type 1)", "",
     nullptr},
    {205, 205, 10, 1, 1, RW, "config.cp16_outputs", "Outputs simulated by the CP16 (CP type 1)", "",
     nullptr},
    {205, 205, 11, 1, 1, RW, "config.serial_mode",
     "Serial mode: 0 Cam-BUS, 1 Standard 9600, 2 Multiuser, 3 S5-L1, 4 3964R n96 (4-byte "
     "words), 5 3964R e38 (2-byte words, 38400)",
     "", "the manual gives mode 4 no baud rate; taken as n96 (9600) from the word width"},
    {205, 205, 12, 1, 1, R, "config.option", "CamCon option: 0 none, 1 PLC, 2 PLC + text, ...", "",
     nullptr},

    // 3.7 / 3.8 Areas 206..213: set and actual values of the PLC logic
    // module, word n-1 = network n. P, M and X list 992 networks; words
    // 256..991 lie beyond RK512's offset byte.
    {206, 206, 0, 200, 1, RW, "plc.set_o",
     "Set value of network O1..O200: timer preset, counter preset or shift register length "
     "(writing resets the timer or counter)",
     "timer 0.1 ms, counter counts, shift register steps", nullptr},
    {207, 207, 0, 992, 1, RW, "plc.set_p", "Set value of network P1..P992",
     "timer 0.1 ms, counter counts, shift register steps", nullptr},
    {208, 208, 0, 992, 1, RW, "plc.set_m", "Set value of network M1..M992",
     "timer 0.1 ms, counter counts, shift register steps", nullptr},
    {209, 209, 0, 992, 1, RW, "plc.set_x", "Set value of network X1..X992",
     "timer 0.1 ms, counter counts, shift register steps", nullptr},
    {210, 210, 0, 200, 1, RW, "plc.actual_o",
     "Actual value of network O1..O200 (timer time, count; a shift register takes only 0, which "
     "clears it)",
     "timer 0.1 ms, counter counts", nullptr},
    {211, 211, 0, 992, 1, RW, "plc.actual_p", "Actual value of network P1..P992",
     "timer 0.1 ms, counter counts", nullptr},
    {212, 212, 0, 992, 1, RW, "plc.actual_m", "Actual value of network M1..M992",
     "timer 0.1 ms, counter counts", nullptr},
    {213, 213, 0, 992, 1, RW, "plc.actual_x", "Actual value of network X1..X992",
     "timer 0.1 ms, counter counts", nullptr},

    // 3.9 Area 214: multi-cam programming; write all 6 words of a type.
    {214, 214, 0, 1, 1, W, "multicam_fixed.program", "Fixed-length multi-cam: program", "",
     nullptr},
    {214, 214, 1, 1, 1, W, "multicam_fixed.output", "Fixed-length multi-cam: output", "", nullptr},
    {214, 214, 2, 1, 1, W, "multicam_fixed.cam_length", "Fixed-length multi-cam: cam length",
     "actual-value units", nullptr},
    {214, 214, 3, 1, 1, W, "multicam_fixed.start", "Fixed-length multi-cam: first point",
     "actual-value units", nullptr},
    {214, 214, 4, 1, 1, W, "multicam_fixed.end", "Fixed-length multi-cam: last point",
     "actual-value units", nullptr},
    {214, 214, 5, 1, 1, W, "multicam_fixed.gap",
     "Fixed-length multi-cam: gap from a switch-off point to the next switch-on point",
     "actual-value units", nullptr},
    {214, 214, 6, 1, 1, W, "multicam_percent.program", "Percentage multi-cam: program", "",
     nullptr},
    {214, 214, 7, 1, 1, W, "multicam_percent.output", "Percentage multi-cam: output", "", nullptr},
    {214, 214, 8, 1, 1, W, "multicam_percent.on_share",
     "Percentage multi-cam: share of each period switched on", "%", nullptr},
    {214, 214, 9, 1, 1, W, "multicam_percent.start",
     "Percentage multi-cam: start of the first switched-on part", "actual-value units", nullptr},
    {214, 214, 10, 1, 1, W, "multicam_percent.end",
     "Percentage multi-cam: end of the last switched-off part", "actual-value units", nullptr},
    {214, 214, 11, 1, 1, W, "multicam_percent.count",
     "Percentage multi-cam: number of cams between start and end", "", nullptr},

    // 3.11 Area 216: one network of the PLC logic module, selected by word 0.
    {216, 216, 0, 1, 1, W, "plc_link.network",
     "Selects the network: O 0, P 256, M 512, X 768 + number - 1; from firmware 8/2008 numbers "
     "above 255 carry bits 10-11, the area stays in bits 8-9",
     "", nullptr},
    {216, 216, 1, 1, 1, RW, "plc_link.block_type",
     "Function block type: 0 standard, 1 SR flip-flop, 2 data flip-flop, ...", "", nullptr},
    {216, 216, 2, 1, 1, RW, "plc_link.value1",
     "Value 1: timer or counter actual value, text message number, or shift register length", "",
     nullptr},
    {216, 216, 3, 1, 1, RW, "plc_link.value2",
     "Value 2: counter reset field, or shift register switch-on dead time", "", nullptr},
    {216, 216, 4, 1, 1, RW, "plc_link.value3",
     "Value 3: shift register switch-off dead time, or activation time in mode 2", "", nullptr},
    {216, 216, 5, 1, 1, RW, "plc_link.shift_dead_time_mode",
     "Shift register output dead-time mode: 0 equal on/off, 1 separate, 2 path-time", "", nullptr},
    {216, 216, 6, 30, 1, RW, "plc_link.symbol",
     "Symbol s of current path p at element 6p + s (5 paths of 6 symbols)", "",
     "symbol encoding is in the PLC manual we lack: high byte operand kind, low byte number "
     "(notes 5)"},

    // 3.19 Areas 241..254: analogue cams of analogue output n (= area - 240).
    {241, 254, 1, 125, 2, RW, "analog_cam.base",
     "Base point 1..125; an empty base reads 0x80000000", "actual-value units", nullptr},
    {241, 254, 2, 125, 2, RW, "analog_cam.value", "Analogue value at base point 1..125", "",
     nullptr},
    {241, 254, 254, 1, 1, R, "analog_cam.count", "Number of base points in use", "", nullptr},
};

// Manual 3.4.1.1 - 3.4.1.10: area 203 words 2..7 per special encoder type.
const SpecialEncoderLayout kSpecialEncoders[] = {
    {0, "ssi", "SSI", {"resolution_bits", "first_bit", "capping", "error_bit", "", ""}, nullptr},
    {1,
     "parallel",
     "Parallel",
     {"resolution", "first_input", "mode_gray0_binary1", "", "", ""},
     nullptr},
    {2, "incremental", "Incremental", {"resolution", "divider", "clear_mode", "", "", ""}, nullptr},
    {3, "multiturn", "Multiturn", {"resolution", "turns", "divider", "", "", ""}, nullptr},
    {4,
     "pll",
     "Phase-locked loop",
     {"pulses_per_input_pulse", "pulses_per_turn", "error_window", "pulse_input", "clear_input",
      "sync_output"},
     nullptr},
    {5,
     "timer",
     "Timer",
     {"resolution", "ms_per_step", "stop_input", "clear_input", "", ""},
     nullptr},
    {6,
     "rs232",
     "RS232",
     {"parameter1", "parameter2", "parameter3", "parameter4", "parameter5", "parameter6"},
     "the manual lists type 6 but describes no parameters; shown raw"},
    {7, "ag615", "AG615", {"resolution", "exploit_or_turns", "", "", "", ""}, nullptr},
    {8,
     "simulation",
     "Speed simulation",
     {"resolution", "pulses_per_second", "stop_input", "clear_input", "", ""},
     nullptr},
    {9,
     "hiperface",
     "Hiperface",
     {"pre_multiplier", "pre_divider", "resolution", "clear_mode", "", ""},
     nullptr},
    {10,
     "ssi2",
     "SSI2 (extended)",
     {"resolution_bits", "first_bit", "speed_bit", "error_bit", "actual_error_bit",
      "mode_gray0_binary1"},
     nullptr},
};

}  // namespace

int TableEntry::indexOf(int word) const {
    const int distance = word - firstWord;
    if (distance < 0 || distance % stride != 0) return -1;
    const int index = distance / stride;
    return index < count ? index : -1;
}

const QList<TableEntry>& tableEntries() {
    static const QList<TableEntry> entries(std::begin(kEntries), std::end(kEntries));
    return entries;
}

const TableEntry* findTableEntry(QStringView key) {
    for (const TableEntry& entry : tableEntries()) {
        if (key == QLatin1String(entry.key)) return &entry;
    }
    return nullptr;
}

std::optional<TableLocation> locateTableWord(int area, int word) {
    for (const TableEntry& entry : tableEntries()) {
        if (!entry.inArea(area)) continue;
        const int index = entry.indexOf(word);
        if (index >= 0) return TableLocation{&entry, index};
    }
    return std::nullopt;
}

QList<const TableEntry*> tableEntriesOfArea(int area) {
    QList<const TableEntry*> entries;
    for (const TableEntry& entry : tableEntries()) {
        if (entry.inArea(area)) entries.append(&entry);
    }
    std::stable_sort(entries.begin(), entries.end(), [](const TableEntry* a, const TableEntry* b) {
        return a->firstWord < b->firstWord;
    });
    return entries;
}

int tableWord(QStringView key, int index) {
    const TableEntry* entry = findTableEntry(key);
    Q_ASSERT_X(entry, "tableWord", "key not in the table map");
    if (!entry || index < 0 || index >= entry->count) return -1;
    return entry->wordOf(index);
}

const QList<SpecialEncoderLayout>& specialEncoderLayouts() {
    static const QList<SpecialEncoderLayout> layouts(std::begin(kSpecialEncoders),
                                                     std::end(kSpecialEncoders));
    return layouts;
}

const SpecialEncoderLayout* findSpecialEncoderLayout(int type) {
    for (const SpecialEncoderLayout& layout : specialEncoderLayouts()) {
        if (layout.type == type) return &layout;
    }
    return nullptr;
}

}  // namespace cambench::comm::table
