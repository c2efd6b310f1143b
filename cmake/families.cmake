# The device families this CamBench is built with: the names of their
# folders, wherever those sit (comm/<family>/, comm/sim/<family>/,
# model/<family>/, ui/<family>/, app/cli/<family>/, tests/<area>/<family>/,
# translations/<family>/, packaging/<family>/). Each family lists its own
# files in a sources.cmake (tests.cmake for tests) in its folders; the
# shell's lists name none of them and include the families' lists through
# cambench_include_family_lists. Adding a family adds its name here (the
# CTests `layering`, `family_sources` and `architecture_doc` read this list
# too).
include_guard(GLOBAL)

set(CAMBENCH_FAMILIES camcon mc1 compax3)

# Includes BASE/<family>/LIST for each family that has one, in the order of
# CAMBENCH_FAMILIES. A macro, not a function: the lists add to the caller's
# targets and variables as if written in its place.
macro(cambench_include_family_lists base list)
  foreach(_cambench_family IN LISTS CAMBENCH_FAMILIES)
    if(EXISTS "${base}/${_cambench_family}/${list}")
      include("${base}/${_cambench_family}/${list}")
    endif()
  endforeach()
endmacro()
