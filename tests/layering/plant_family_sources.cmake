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

function(run_check out_rc out_text)
  execute_process(COMMAND ${CMAKE_COMMAND} -DROOT=${SCRATCH} -P ${CHECK}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(${out_rc} ${rc} PARENT_SCOPE)
  set(${out_text} "${out}${err}" PARENT_SCOPE)
endfunction()

run_check(rc text)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the untouched copy of the lists fails the check:\n${text}")
endif()

# Appends LINE to LIST (a path under SCRATCH), runs the check, restores the
# list; EXPECT is "caught" or "passes".
function(plant list line expect why)
  set(path "${SCRATCH}/${list}")
  file(READ "${path}" original)
  string(REGEX MATCHALL "\n" newlines "${original}")
  list(LENGTH newlines count)
  math(EXPR number "${count} + 1")
  file(APPEND "${path}" "${line}\n")
  run_check(rc text)
  file(WRITE "${path}" "${original}")
  if(expect STREQUAL "caught")
    if(rc EQUAL 0)
      message(SEND_ERROR "not caught (${why}): ${list} with \"${line}\"")
    elseif(NOT text MATCHES "${list}:${number}: names")
      message(SEND_ERROR "caught, but not as ${list}:${number} (${why}):\n${text}")
    else()
      message(STATUS "caught (${why}): ${list}:${number}")
    endif()
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
