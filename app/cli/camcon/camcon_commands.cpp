#include "camcon_commands.h"

namespace cambench::cli {

namespace {

QString camConHelp() {
    return QStringLiteral(
        "  (the table interface, 3964r-n96 and 3964r-e38, has no users, names, EEPROM backup\n"
        "  or raw commands)\n"
        "  info [--json]                    identity and capacities, \"key: value\" lines\n"
        "  status [--json]                  position, speed, program, error state, outputs\n"
        "  scan [--json]                    Multiuser: device numbers that answer, one a line;\n"
        "                                   Cam-BUS: every user, \"3: CamCon\", \"12: other\"\n"
        "  cams read --program P [--output O] [-o FILE]   CSV, header \"output,cam,on,off\"\n"
        "  cams write --program P FILE      replaces exactly the tracks that FILE lists\n"
        "  deadtimes read [-o FILE] | deadtimes write FILE     CSV \"output,deadtime\" (0.1 ms);\n"
        "                                   the table interface adds \",mode,on,off\"\n"
        "  names read [-o FILE] | names write FILE        CSV \"kind,number,name\" "
        "(output|program)\n"
        "  settings read [-o FILE] | settings write FILE [--communication-settings KEYS]\n"
        "                                   JSON, system and encoder settings; the file's\n"
        "                                   protocol and deviceNumber are left out unless KEYS\n"
        "                                   names them (e.g. protocol,deviceNumber): they\n"
        "                                   decide how the device is reached\n"
        "  users list                       names and rights, numbers masked\n"
        "  plc read [-o FILE] | plc write FILE            JSON\n"
        "  project read [-o FILE] [--with-user-numbers]   everything on the device as a project\n"
        "  project write FILE [--communication-settings KEYS]\n"
        "                                   makes the device hold the project's contents\n"
        "                                   (its communication settings only as KEYS names them)\n"
        "  diff A B [--program P [--program-b Q]] [--json]\n"
        "                                   the cams that differ between A and B (project or\n"
        "                                   CSV files, or device: needs --program), one a line;\n"
        "                                   exit 0 equal, 1 differ; --git: git's diff driver\n"
        "  timing --program P --speed V [--min-pulse MS] [--axis rotary|linear]\n"
        "         [--project FILE] [--json] where each output switches at speed V (1/min on a\n"
        "                                   rotary axis, pos/s on a linear one): shift, shortest\n"
        "                                   cam, the speed above which cams vanish or merge;\n"
        "                                   --min-pulse 12 | 3=12,4=8.5 | 5,3=12 (ms)\n"
        "  backup -o FILE                   whole EEPROM image\n"
        "  restore FILE [--replacement] [--no-safety-backup]\n"
        "                                   checks FILE, matches it against the device (only the\n"
        "                                   device it was taken from, else nothing is written,\n"
        "                                   exit 4; --replacement, formerly --force: this device\n"
        "                                   replaces that one), saves a\n"
        "                                   safety backup FILE.safety-<UTC time>.json, then "
        "erases\n"
        "                                   and writes\n"
        "  verify FILE                      compare device with image; exit 0 when equal,\n"
        "                                   1 when the device differs\n"
        "  backup-line -o DIR [--devices LIST] [--resume]\n"
        "                                   Multiuser: back up every device that answers (or\n"
        "                                   LIST, e.g. 1,2,5) into DIR with manifest.json; goes "
        "on\n"
        "                                   past a device that fails; --resume skips devices\n"
        "                                   saved before whose files still check; exit 0 only "
        "when\n"
        "                                   every device was saved, 3 otherwise\n"
        "  verify-line DIR                  compare every device with its image in DIR; exit 0\n"
        "                                   when all are equal, 1 otherwise\n"
        "  raw \"COMMAND\"                    one ASCII command, checksum added; prints the reply\n"
        "\n"
        "Table interface only (elsewhere a read fails, a write reports \"not sent\"):\n"
        "  analogue read [--output A] [-o FILE]   CSV \"output,position,value\" of analogue\n"
        "                                   outputs 1..14 (\"3,,\": output 3 has no points)\n"
        "  analogue write FILE              each analogue output FILE lists gets its points\n"
        "  programming read                 the programming program and its select mode\n"
        "  programming write P [--mode slow|direct|at-value] [--switch-value N]\n"
        "                                   what is not given stays as on the device\n"
        "  eeprom-lock read | lock | unlock locked: later changes are held in RAM only\n"
        "\n"
        "S7-CP340 coupling (table interface only): the short commands a PLC sends\n"
        "  short status [--json]            0x01: actual value, speed, program, device status,\n"
        "                                   outputs (no virtual inputs are sent)\n"
        "  short reset-errors               0x02, then the device status it leaves\n"
        "  short program N                  0x03, then the active program the device reports\n"
        "  short track read O [--program P] 0x04: CSV \"output,cam,on,off\" (default: the\n"
        "                                   active program)\n"
        "  short track write O FILE --program P   0x05 (at most 14 cams), read back with 0x04\n"
        "  short deadtime read O            0x06: CSV \"output,deadtime\" (0.1 ms)\n"
        "  short deadtime write O VALUE     0x07 (VALUE in 0.1 ms), read back with 0x06\n");
}

}  // namespace

void registerCamConCommands(FamilyCommands& commands) {
    const std::pair<const char*, int (*)(CliSession&, CommandArgs&)> groups[] = {
        {"info", runInfo},
        {"status", runStatus},
        {"scan", runScan},
        {"raw", runRaw},
        {"cams", runCams},
        {"deadtimes", runDeadTimes},
        {"names", runNames},
        {"settings", runSettings},
        {"users", runUsers},
        {"plc", runPlc},
        {"backup", runBackup},
        {"restore", runRestore},
        {"verify", runVerify},
        {"project", runProject},
        {"backup-line", runBackupLine},
        {"verify-line", runVerifyLine},
        {"short", runShortCommands},
        {"analogue", runAnalogue},
        {"programming", runProgramming},
        {"eeprom-lock", runEepromLock},
        {"diff", runDiff},
        {"timing", runTiming},
    };
    // The line commands are for a bus: without --protocol (or a port that
    // names one) they speak Multiuser.
    const QStringList lineCommands = {QStringLiteral("backup-line"), QStringLiteral("verify-line")};
    for (const auto& [name, run] : groups) {
        const QString command = QLatin1String(name);
        commands.add(command, run,
                     lineCommands.contains(command) ? QStringLiteral("multiuser") : QString());
    }
    commands.addHelp(camConHelp());
}

}  // namespace cambench::cli
