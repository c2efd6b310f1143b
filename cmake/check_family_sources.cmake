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
# word with a folder named after a family (camcon/, mc1/, compax3/, as the
# first folder of the word or after a slash) that ends in a file name with
# an extension ("camcon/sim_axis.cpp", "${X}/mc1/sources.cmake"). A folder
# alone (add_subdirectory) and a file whose name merely holds a family's
# name (fuzz/mc1_decoder.cmake) are no violation. A path built from
# variables that hold a family folder is not seen. The checks' own scripts
# (tests/layering/) name family files as what they plant: not lists of
# sources, not checked.
cmake_minimum_required(VERSION 3.25)

if(NOT ROOT)
  message(FATAL_ERROR "family_sources: pass -DROOT=<source dir>")
endif()
include("${ROOT}/cmake/families.cmake")
string(JOIN "|" family_names ${CAMBENCH_FAMILIES})
set(family_file "(^|[ \t(\"/])(${family_names})/[^ \t()\"]*\\.[A-Za-z0-9_]+")

# The lists of the tree: every folder but build trees and hidden ones.
file(GLOB top RELATIVE "${ROOT}" "${ROOT}/*")
set(lists)
foreach(entry IN LISTS top)
  if(entry MATCHES "^(\\.|build)")
    continue()
  endif()
  if(IS_DIRECTORY "${ROOT}/${entry}")
    file(GLOB_RECURSE found RELATIVE "${ROOT}" "${ROOT}/${entry}/CMakeLists.txt"
         "${ROOT}/${entry}/*.cmake")
    list(APPEND lists ${found})
  elseif(entry MATCHES "(^CMakeLists\\.txt|\\.cmake)$")
    list(APPEND lists "${entry}")
  endif()
endforeach()
list(SORT lists)

set(violations 0)
set(checked 0)
foreach(list_file IN LISTS lists)
  string(REPLACE "/" ";" parts "${list_file}")
  list(POP_BACK parts)
  set(in_family FALSE)
  foreach(part IN LISTS parts)
    if(part IN_LIST CAMBENCH_FAMILIES)
      set(in_family TRUE)
    endif()
  endforeach()
  if(in_family OR list_file MATCHES "^tests/layering/")
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
