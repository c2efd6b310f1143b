# docs/architecture.md's list of the files outside the family folders that
# name a family ("Adding a family") must be the tree's (CTest
# `architecture_doc`; CMake's script mode):
#   cmake -DROOT=<source dir> -P cmake/check_architecture_doc.cmake
# Fails naming each file the tree has and the list lacks, and each the list
# has and the tree does not.
#
# The rule (the doc states it too): a file outside the family folders names
# a family when its path or a line of it holds a family's id (the
# CAMBENCH_FAMILIES of cmake/families.cmake) as a word: in lower case, with
# no letter or digit on either side (for a family xy: "comm/sim/xy/",
# "xy_bench", "--family xy"; not "XyDevice", not "xyParts"). tests/ and
# bench/ are read like the rest (a family's tests sit in
# tests/<area>/<family>/). Not read: docs/ (the doc itself and the
# pictures), translations/*.ts (written by lupdate), build trees and hidden
# folders but .ci/.
cmake_minimum_required(VERSION 3.25)
include("${CMAKE_CURRENT_LIST_DIR}/tree_checks.cmake")

set(word "(^|[^A-Za-z0-9])(${CAMBENCH_FAMILY_NAMES})([^A-Za-z0-9]|$)")
set(doc "docs/architecture.md")

# The tree's files in the rule's scope.
cambench_tree_files(files SKIP docs)

set(tree)
foreach(file IN LISTS files)
  if(file MATCHES "^translations/[^/]*\\.ts$")
    continue()
  endif()
  cambench_family_of("${file}" family)
  if(family)
    continue()
  endif()
  get_filename_component(name "${file}" NAME)
  if(name MATCHES "${word}")
    list(APPEND tree "${file}")
    continue()
  endif()
  file(STRINGS "${ROOT}/${file}" hits REGEX "${word}" LIMIT_COUNT 1)
  if(hits)
    list(APPEND tree "${file}")
  endif()
endforeach()

# The doc's list: the table rows "| `path` | why |" between its markers.
file(STRINGS "${ROOT}/${doc}" doc_lines)
set(listed)
set(inside FALSE)
foreach(line IN LISTS doc_lines)
  if(line MATCHES "<!-- files naming a family: begin -->")
    set(inside TRUE)
  elseif(line MATCHES "<!-- files naming a family: end -->")
    set(inside FALSE)
  elseif(inside AND line MATCHES "^\\| `([^`]+)` \\|")
    list(APPEND listed "${CMAKE_MATCH_1}")
  endif()
endforeach()
if(NOT listed)
  message(FATAL_ERROR "architecture_doc: ${doc} has no list between "
                      "\"<!-- files naming a family: begin -->\" and \"... end -->\"")
endif()

set(differences 0)
foreach(file IN LISTS tree)
  if(NOT file IN_LIST listed)
    message(NOTICE "${file}: names a family, but ${doc}'s list lacks it")
    math(EXPR differences "${differences} + 1")
  endif()
endforeach()
foreach(file IN LISTS listed)
  if(NOT file IN_LIST tree)
    message(NOTICE "${doc}: lists ${file}, which names no family (or is gone)")
    math(EXPR differences "${differences} + 1")
  endif()
endforeach()
if(differences GREATER 0)
  message(FATAL_ERROR "architecture_doc: ${doc}'s list of the files outside the family "
                      "folders that name a family differs from the tree in ${differences} "
                      "file(s)")
endif()
list(LENGTH tree count)
message(STATUS "architecture_doc: the ${count} files outside the family folders that name a "
               "family are the ones ${doc} lists")
