# Proves that the `architecture_doc` check fails where it must: copies the
# tree (without build trees and hidden folders, which the check does not
# read) to SCRATCH, then names a family in a shell file the doc's list
# lacks, and drops a file from the list, and expects the check to name
# each.
#   cmake -DROOT=<source dir> -DSCRATCH=<dir> -DCHECK=<check_architecture_doc.cmake> -P plant_architecture_doc.cmake
cmake_minimum_required(VERSION 3.25)

file(REMOVE_RECURSE "${SCRATCH}")
file(MAKE_DIRECTORY "${SCRATCH}")
file(GLOB top RELATIVE "${ROOT}" "${ROOT}/*" "${ROOT}/.ci")
foreach(entry IN LISTS top)
  if(NOT entry MATCHES "^(build.*|\\..*)$" OR entry STREQUAL ".ci")
    file(COPY "${ROOT}/${entry}" DESTINATION "${SCRATCH}")
  endif()
endforeach()

include(${CMAKE_CURRENT_LIST_DIR}/run_check.cmake)
expect_untouched_passes()

# A shell header that names a family in a comment, unlisted.
run_check_planted(ui/theme.h "// as the mc1 pages do" rc text number)
if(rc EQUAL 0 OR NOT text MATCHES "ui/theme.h: names a family, but docs/architecture.md's list lacks it")
  message(SEND_ERROR "an unlisted file naming a family was not named:\n${text}")
else()
  message(STATUS "caught: ui/theme.h names a family, unlisted")
endif()

# A listed file dropped from the doc's list.
set(doc "${SCRATCH}/docs/architecture.md")
file(READ "${doc}" original)
string(REPLACE "| `ui/shell.h` |" "| `ui/gone.h` |" changed "${original}")
file(WRITE "${doc}" "${changed}")
run_check(rc text)
file(WRITE "${doc}" "${original}")
if(rc EQUAL 0 OR NOT text MATCHES "ui/shell.h: names a family, but"
   OR NOT text MATCHES "lists ui/gone.h, which names no family")
  message(SEND_ERROR "a list that differs from the tree was not named:\n${text}")
else()
  message(STATUS "caught: ui/shell.h missing from the list, ui/gone.h too many")
endif()
