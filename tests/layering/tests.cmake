# The house's rules, each a check in CMake's script mode over the source
# tree (cmake/check_<rule>.cmake, CTest <rule>) and a proof that it fails
# where it must: a script that plants a violation in a scratch copy of the
# tree and expects the check to name it (layering/<plant>.cmake, CTest
# <rule>_<what it catches>). Paths relative to tests/.
function(cambench_add_tree_check rule plant proof)
  add_test(NAME ${rule}
    COMMAND ${CMAKE_COMMAND} -DROOT=${PROJECT_SOURCE_DIR}
            -P ${PROJECT_SOURCE_DIR}/cmake/check_${rule}.cmake)
  add_test(NAME ${rule}_${proof}
    COMMAND ${CMAKE_COMMAND} -DROOT=${PROJECT_SOURCE_DIR}
            -DSCRATCH=${CMAKE_CURRENT_BINARY_DIR}/${rule}-scratch
            -DCHECK=${PROJECT_SOURCE_DIR}/cmake/check_${rule}.cmake
            -P ${CMAKE_CURRENT_SOURCE_DIR}/layering/${plant}.cmake)
  set_tests_properties(${rule} ${rule}_${proof} PROPERTIES TIMEOUT 300)
endfunction()

# The layering rules over the includes of the whole tree (issue 31, item 3).
cambench_add_tree_check(layering plant_includes catches_planted_includes)
# Each family lists its own sources (issue 31, item 2): no shell CMake list
# names a file inside a family folder.
cambench_add_tree_check(family_sources plant_family_sources catches_planted_names)
# docs/architecture.md's list of the files outside the family folders that
# name a family is the tree's (issue 31, item 4).
cambench_add_tree_check(architecture_doc plant_architecture_doc catches_differences)
