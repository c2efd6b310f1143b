# How the package's texts (desktop entry, man pages, Debian description)
# name the Parker Compax3 family; packaging/CMakeLists.txt joins every
# family's, in the order of CAMBENCH_FAMILIES. No semicolons in the texts:
# they are CMake list items (the keywords are a list of their own).
list(APPEND CAMBENCH_PACKAGE_FAMILIES "Parker Compax3 servo drives")
list(APPEND CAMBENCH_PACKAGE_FAMILIES_DE "Servoantriebe Parker Compax3")
list(APPEND CAMBENCH_PACKAGE_KINDS "servo drives")
list(APPEND CAMBENCH_PACKAGE_DEVICES "Compax3")
list(APPEND CAMBENCH_PACKAGE_KEYWORDS Compax3 Parker servo drive)
list(APPEND CAMBENCH_PACKAGE_KEYWORDS_DE Compax3 Parker Servoantrieb Antrieb)
list(APPEND CAMBENCH_PACKAGE_PARAGRAPHS
  "Parker Compax3 servo drives: any object, live values, motion, parameter sets
saved and put back on a replacement drive.")
