# The layering rules of docs/architecture.md, checked over the project's own
# #include "..." lines (CTest `layering`; CMake's script mode, so a fresh
# machine needs nothing beyond the build's own tools):
#   cmake -DROOT=<source dir> -P cmake/check_layering.cmake
# Prints each violation as "FILE:LINE: ..." and fails when there is one.
#
#  - model/ includes nothing of comm/, ui/, app/;
#  - comm/ includes model/ and comm/, never ui/ or app/;
#  - ui/ reaches the device through comm's device interfaces and use cases,
#    never a transport, engine, worker or simulator header (comm/transport,
#    comm/engine, comm/worker, comm/sim), and includes nothing of app/;
#  - the family folders (named as CAMBENCH_FAMILIES of cmake/families.cmake,
#    wherever they sit) never include each other;
#  - the shell (everything outside the family folders) includes no family
#    header, except the one registration place, kRegistrationPlace
#    (app/registry/builtin_registry.cpp: one line per family).
#
# An include is resolved as the compiler does for quotes: beside the
# including file first, then from the source root. Includes that resolve to
# no file of the tree (generated headers such as cambench_version.h) are
# not checked.

cmake_minimum_required(VERSION 3.25)
include("${CMAKE_CURRENT_LIST_DIR}/tree_checks.cmake")

set(kLayers model comm ui app)
# The only shell file that may include a family's header: the list of the
# built-in families, each through its parts file (app/registry/<family>/).
set(kRegistrationPlace "^app/registry/builtin_registry\\.cpp$")
# What ui/ must not reach into: the device is behind comm's interfaces.
set(kUiForbidden "^comm/(transport|engine|worker|sim)/")

function(layering_is_registration_place path out)
  set(result FALSE)
  if(path MATCHES "${kRegistrationPlace}")
    set(result TRUE)
  endif()
  set(${out} ${result} PARENT_SCOPE)
endfunction()

# The 1-based line of `text` in `file` (the first one that holds it).
function(layering_line_of file text out)
  file(READ "${ROOT}/${file}" content)
  string(FIND "${content}" "${text}" position)
  string(SUBSTRING "${content}" 0 ${position} before)
  string(REGEX MATCHALL "\n" newlines "${before}")
  list(LENGTH newlines count)
  math(EXPR line "${count} + 1")
  set(${out} ${line} PARENT_SCOPE)
endfunction()

set(files)
foreach(layer IN LISTS kLayers)
  file(GLOB_RECURSE found RELATIVE "${ROOT}" "${ROOT}/${layer}/*.h" "${ROOT}/${layer}/*.cpp")
  list(APPEND files ${found})
endforeach()
list(SORT files)

set(violations 0)
foreach(file IN LISTS files)
  string(REGEX MATCH "^[^/]+" layer "${file}")
  get_filename_component(folder "${file}" DIRECTORY)
  cambench_family_of("${file}" family)
  layering_is_registration_place("${file}" registers)
  file(STRINGS "${ROOT}/${file}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"[^\"]+\"")
  foreach(include_line IN LISTS includes)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*$" "\\1" named "${include_line}")
    if(EXISTS "${ROOT}/${folder}/${named}" AND NOT IS_DIRECTORY "${ROOT}/${folder}/${named}")
      set(target "${folder}/${named}")
    elseif(EXISTS "${ROOT}/${named}" AND NOT IS_DIRECTORY "${ROOT}/${named}")
      set(target "${named}")
    else()
      continue()
    endif()
    cmake_path(NORMAL_PATH target)
    string(REGEX MATCH "^[^/]+" target_layer "${target}")
    cambench_family_of("${target}" target_family)

    set(broken "")
    if(layer STREQUAL "model" AND target_layer MATCHES "^(comm|ui|app)$")
      set(broken "model/ includes nothing of ${target_layer}/")
    elseif(layer STREQUAL "comm" AND target_layer MATCHES "^(ui|app)$")
      set(broken "comm/ includes nothing of ${target_layer}/")
    elseif(layer STREQUAL "ui" AND target_layer STREQUAL "app")
      set(broken "ui/ includes nothing of app/")
    elseif(layer STREQUAL "ui" AND target MATCHES "${kUiForbidden}")
      set(broken "ui/ reaches the device through comm's device interfaces and use cases, "
                 "never a transport, engine, worker or simulator header")
    elseif(family AND target_family AND NOT family STREQUAL target_family)
      set(broken "the ${family} family includes nothing of the ${target_family} family")
    elseif(NOT family AND target_family AND NOT registers)
      set(broken "the shell names no family (only app/registry/builtin_registry.cpp does); "
                 "this includes the ${target_family} family")
    endif()
    if(broken)
      layering_line_of("${file}" "${include_line}" line)
      string(JOIN "" reason ${broken})
      message(NOTICE "${file}:${line}: includes \"${named}\" (${target}): ${reason}")
      math(EXPR violations "${violations} + 1")
    endif()
  endforeach()
endforeach()

list(LENGTH files checked)
if(violations GREATER 0)
  message(FATAL_ERROR "layering: ${violations} include(s) break the layering rules "
                      "(docs/architecture.md); ${checked} files checked")
endif()
message(STATUS "layering: ${checked} files checked, every include keeps the rules")
