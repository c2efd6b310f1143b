# How the package's texts (desktop entry, man pages, Debian description)
# name the Digitronic CamCon family; packaging/CMakeLists.txt joins every
# family's, in the order of CAMBENCH_FAMILIES. No semicolons in the texts:
# they are CMake list items (the keywords are a list of their own).
list(APPEND CAMBENCH_PACKAGE_FAMILIES "Digitronic CamCon cam controllers")
list(APPEND CAMBENCH_PACKAGE_FAMILIES_DE "Nockenschaltwerke Digitronic CamCon")
list(APPEND CAMBENCH_PACKAGE_KINDS "cam controllers")
list(APPEND CAMBENCH_PACKAGE_DEVICES "CamCon")
list(APPEND CAMBENCH_PACKAGE_KEYWORDS CamCon Digitronic cam EEPROM)
list(APPEND CAMBENCH_PACKAGE_KEYWORDS_DE CamCon Digitronic Nocken Nockenschaltwerk EEPROM)
list(APPEND CAMBENCH_PACKAGE_PARAGRAPHS
  "Digitronic CamCon electronic cam controllers (DC16/40/50/51/90/115/190/300):
edit cam programs offline, program and read devices over RS232/RS485 (ASCII
Standard and Multiuser, the table interface, Cam-BUS), watch the machine run,
back up and restore a device's whole EEPROM.")
