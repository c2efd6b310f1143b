# What the checks over the source tree share (check_layering.cmake,
# check_family_sources.cmake, check_architecture_doc.cmake; CMake's script
# mode, ROOT the source dir): the families' folders and the tree's files.
include_guard(GLOBAL)
include("${CMAKE_CURRENT_LIST_DIR}/families.cmake")

if(NOT ROOT)
  message(FATAL_ERROR "pass -DROOT=<source dir> to ${CMAKE_SCRIPT_MODE_FILE}")
endif()
# The families' ids as alternatives of a regular expression: "a|b|c".
string(JOIN "|" CAMBENCH_FAMILY_NAMES ${CAMBENCH_FAMILIES})

# The family whose folder `path` lies in (a folder named after one,
# wherever it sits), or "" for the shell.
function(cambench_family_of path out)
  set(family "")
  string(REPLACE "/" ";" parts "${path}")
  list(POP_BACK parts)  # the file name itself names no folder
  foreach(part IN LISTS parts)
    if(part IN_LIST CAMBENCH_FAMILIES)
      set(family "${part}")
      break()
    endif()
  endforeach()
  set(${out} "${family}" PARENT_SCOPE)
endfunction()

# The files of the tree below ROOT (relative, sorted) whose names match one
# of GLOBS (default: all), leaving out build trees, hidden folders but
# .ci/, and the top-level folders named in SKIP.
function(cambench_tree_files out)
  cmake_parse_arguments(T "" "" "SKIP;GLOBS" ${ARGN})
  if(NOT T_GLOBS)
    set(T_GLOBS "*")
  endif()
  file(GLOB top RELATIVE "${ROOT}" "${ROOT}/*" "${ROOT}/.ci")
  set(files)
  foreach(entry IN LISTS top)
    if((entry MATCHES "^(build|\\.)" AND NOT entry STREQUAL ".ci") OR entry IN_LIST T_SKIP
       OR NOT IS_DIRECTORY "${ROOT}/${entry}")
      continue()
    endif()
    foreach(glob IN LISTS T_GLOBS)
      file(GLOB_RECURSE found RELATIVE "${ROOT}" "${ROOT}/${entry}/${glob}")
      list(APPEND files ${found})
    endforeach()
  endforeach()
  foreach(glob IN LISTS T_GLOBS)
    file(GLOB found LIST_DIRECTORIES false RELATIVE "${ROOT}" "${ROOT}/${glob}")
    list(APPEND files ${found})
  endforeach()
  list(REMOVE_DUPLICATES files)
  list(SORT files)
  set(${out} ${files} PARENT_SCOPE)
endfunction()
