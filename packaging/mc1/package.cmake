# How the package's texts (desktop entry, man pages, Debian description)
# name the MICRO DESIGN MC100/MC200 family; packaging/CMakeLists.txt joins
# every family's, in the order of CAMBENCH_FAMILIES. No semicolons in the
# texts: they are CMake list items (the keywords are a list of their own).
list(APPEND CAMBENCH_PACKAGE_FAMILIES "MICRO DESIGN MC100/MC200 motion controllers")
list(APPEND CAMBENCH_PACKAGE_FAMILIES_DE "Bewegungssteuerungen MICRO DESIGN MC100/MC200")
list(APPEND CAMBENCH_PACKAGE_KINDS "motion controllers")
list(APPEND CAMBENCH_PACKAGE_DEVICES "MC100/MC200")
list(APPEND CAMBENCH_PACKAGE_KEYWORDS MC100 MC200 "MICRO DESIGN" motion axis)
list(APPEND CAMBENCH_PACKAGE_KEYWORDS_DE MC100 MC200 "MICRO DESIGN" Bewegungssteuerung Achse)
list(APPEND CAMBENCH_PACKAGE_PARAGRAPHS
  "MICRO DESIGN MC100/MC200 motion controllers: variables, flags and I/O, the
PLC program, axes, memory, backup and restore.")
