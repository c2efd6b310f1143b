# The layering rules over the includes of the whole tree (issue 31, item 3),
# and the check itself: a wrong include planted in a scratch copy of the tree
# must make it fail with the file and line (paths relative to tests/).
add_test(NAME layering
  COMMAND ${CMAKE_COMMAND} -DROOT=${PROJECT_SOURCE_DIR}
          -P ${PROJECT_SOURCE_DIR}/cmake/check_layering.cmake)
add_test(NAME layering_catches_planted_includes
  COMMAND ${CMAKE_COMMAND} -DROOT=${PROJECT_SOURCE_DIR}
          -DSCRATCH=${CMAKE_CURRENT_BINARY_DIR}/layering-scratch
          -DCHECK=${PROJECT_SOURCE_DIR}/cmake/check_layering.cmake
          -P ${CMAKE_CURRENT_SOURCE_DIR}/layering/plant_includes.cmake)
set_tests_properties(layering layering_catches_planted_includes PROPERTIES TIMEOUT 300)
# Each family lists its own sources (issue 31, item 2): no shell CMake list
# names a file inside a family folder; and the check itself, on a planted line.
add_test(NAME family_sources
  COMMAND ${CMAKE_COMMAND} -DROOT=${PROJECT_SOURCE_DIR}
          -P ${PROJECT_SOURCE_DIR}/cmake/check_family_sources.cmake)
add_test(NAME family_sources_catches_planted_names
  COMMAND ${CMAKE_COMMAND} -DROOT=${PROJECT_SOURCE_DIR}
          -DSCRATCH=${CMAKE_CURRENT_BINARY_DIR}/family-sources-scratch
          -DCHECK=${PROJECT_SOURCE_DIR}/cmake/check_family_sources.cmake
          -P ${CMAKE_CURRENT_SOURCE_DIR}/layering/plant_family_sources.cmake)
set_tests_properties(family_sources family_sources_catches_planted_names PROPERTIES TIMEOUT 300)
