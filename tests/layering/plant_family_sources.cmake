# Proves that the `family_sources` check fails where it must: copies the
# tree's CMake lists to SCRATCH, then plants a line naming a family's file
# into a shell list and expects the check to fail naming that list and
# line; the same line in the family's own list passes.
#   cmake -DROOT=<source dir> -DSCRATCH=<dir> -DCHECK=<check_family_sources.cmake> -P plant_family_sources.cmake
cmake_minimum_required(VERSION 3.25)

file(REMOVE_RECURSE "${SCRATCH}")
file(COPY "${ROOT}/" DESTINATION "${SCRATCH}" FILES_MATCHING
     PATTERN "CMakeLists.txt" PATTERN "*.cmake"
     PATTERN ".*" EXCLUDE PATTERN "build*" EXCLUDE)

include(${CMAKE_CURRENT_LIST_DIR}/run_check.cmake)
expect_untouched_passes()

# Appends LINE to LIST (a path under SCRATCH), runs the check, restores the
# list; EXPECT is "caught" or "passes".
function(plant list line expect why)
  run_check_planted("${list}" "${line}" rc text number)
  if(expect STREQUAL "caught")
    expect_caught(${rc} "${text}" "${list}:${number}: names" "${list}:${number}" "${why}")
  elseif(NOT rc EQUAL 0)
    message(SEND_ERROR "refused though allowed (${why}): ${list} with \"${line}\":\n${text}")
  else()
    message(STATUS "passes (${why}): ${list}")
  endif()
endfunction()

plant(comm/sim/sources.cmake "target_sources(cambench_sim PRIVATE camcon/sim_axis.cpp)"
      caught "the simulator host names a simulated CamCon file")
plant(ui/CMakeLists.txt "include(mc1/sources.cmake)"
      caught "the shell includes a family's list by name")
plant(tests/ui/tests.cmake "cambench_add_test(t SOURCES ui/compax3/tst_x.cpp)"
      caught "a shell test list names a family's test")
plant(comm/sim/camcon/sources.cmake "target_sources(cambench_sim PRIVATE camcon/sim_axis.cpp)"
      passes "a family lists its own file")
plant(tests/comm/tests.cmake "include(\${CMAKE_CURRENT_LIST_DIR}/../fuzz/mc1_decoder.cmake)"
      passes "a shell file whose name holds a family's name")
