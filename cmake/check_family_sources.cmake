# Each family lists its own sources (docs/architecture.md, "Build layout"):
# no CMake list of the shell (a CMakeLists.txt or *.cmake outside the family
# folders) names a file inside a family folder. The shell's lists include
# the families' own lists through cambench_include_family_lists
# (cmake/families.cmake) and name none of their files (CTest
# `family_sources`; CMake's script mode):
#   cmake -DROOT=<source dir> -P cmake/check_family_sources.cmake
# Prints each violation as "FILE:LINE: ..." and fails when there is one.
#
# The rule, read on each line of a shell list with its comment cut off: a
# word with a folder named after a family (CAMBENCH_FAMILIES of
# cmake/families.cmake; for a family xy: xy/, as the first folder of the
# word or after a slash) that ends in a file name with an extension
# ("xy/sim_xy.cpp", "${X}/xy/sources.cmake"). A folder alone
# (add_subdirectory) and a file whose name merely holds a family's name
# (fuzz/xy_decoder.cmake) are no violation. A path built from
# variables that hold a family folder is not seen. The checks' own scripts
# (tests/layering/) name family files as what they plant: not lists of
# sources, not checked.
cmake_minimum_required(VERSION 3.25)
include("${CMAKE_CURRENT_LIST_DIR}/tree_checks.cmake")

set(family_names "${CAMBENCH_FAMILY_NAMES}")
set(family_file "(^|[ \t(\"/])(${family_names})/[^ \t()\"]*\\.[A-Za-z0-9_]+")

cambench_tree_files(lists GLOBS CMakeLists.txt *.cmake)

set(violations 0)
set(checked 0)
foreach(list_file IN LISTS lists)
  cambench_family_of("${list_file}" family)
  if(family OR list_file MATCHES "^tests/layering/")
    continue()
  endif()
  math(EXPR checked "${checked} + 1")
  # Line by line, numbered: file(STRINGS) would drop the empty ones.
  file(READ "${ROOT}/${list_file}" content)
  string(REPLACE ";" "," content "${content}")
  string(REPLACE "\n" ";" lines "${content}")
  set(number 0)
  foreach(line IN LISTS lines)
    math(EXPR number "${number} + 1")
    string(REGEX REPLACE "#.*$" "" code "${line}")
    if(code MATCHES "${family_file}")
      string(REGEX MATCH "(${family_names})/[^ \t()\"]*" named "${CMAKE_MATCH_0}")
      message(NOTICE "${list_file}:${number}: names \"${named}\", a file of the "
                     "${CMAKE_MATCH_1} family: list it in that family's own sources.cmake "
                     "(or tests.cmake), which the shell includes through "
                     "cambench_include_family_lists")
      math(EXPR violations "${violations} + 1")
    endif()
  endforeach()
endforeach()

if(violations GREATER 0)
  message(FATAL_ERROR "family_sources: ${violations} line(s) of the shell's CMake lists name "
                      "a file of a family (docs/architecture.md); ${checked} lists checked")
endif()
message(STATUS "family_sources: ${checked} shell CMake lists checked, none names a family's file")
