# Proves that the `layering` check fails where it must: copies the checked
# folders of the tree to SCRATCH, then plants one wrong include at a time at
# the end of a file and expects the check to fail naming that file and line
# (and to pass again once the file is restored). The untouched copy must
# pass first, so that a failure below is the planted include's doing.
#   cmake -DROOT=<source dir> -DSCRATCH=<dir> -DCHECK=<check_layering.cmake> -P plant_includes.cmake
cmake_minimum_required(VERSION 3.25)

file(REMOVE_RECURSE "${SCRATCH}")
file(MAKE_DIRECTORY "${SCRATCH}")
foreach(layer model comm ui app)
  file(COPY "${ROOT}/${layer}" DESTINATION "${SCRATCH}")
endforeach()

include(${CMAKE_CURRENT_LIST_DIR}/run_check.cmake)
expect_untouched_passes()

set(failures 0)
# FILE, the include planted at its end, and why it is wrong.
function(expect_violation file include why)
  set(path "${SCRATCH}/${file}")
  if(NOT EXISTS "${path}")
    message(SEND_ERROR "${file} is gone from the tree: pick another file for \"${why}\"")
    return()
  endif()
  run_check_planted("${file}" "#include \"${include}\"" rc text line)
  expect_caught(${rc} "${text}" "${file}:${line}: includes \"${include}\"" "${file}:${line}"
                "${why}")
endfunction()

expect_violation(model/atomic_file.h comm/device/progress.h "model includes comm")
expect_violation(model/json_file.h ui/device_session.h "model includes ui")
expect_violation(comm/device/progress.h ui/device_session.h "comm includes ui")
expect_violation(comm/engine/engine_logging.h app/cli/exit_codes.h "comm includes app")
expect_violation(ui/device_session.h comm/worker/comm_worker.h "ui includes the worker")
expect_violation(ui/main_window.cpp comm/engine/request_engine.h "ui includes the engine")
expect_violation(ui/camcon/backup_page.h comm/transport/transport.h "ui includes a transport")
expect_violation(comm/mc1/mc1_address.h comm/camcon/camcon_device.h "a family includes another")
expect_violation(comm/mc1/mc1_address.h ../compax3/compax3_device.h
                 "a family includes another by a relative path")
expect_violation(ui/main_window.cpp ui/camcon/backup_page.h "the shell names a family")
expect_violation(app/cli/main.cpp app/cli/camcon/camcon_commands.h
                 "a program's main names a family's part")
expect_violation(app/registry/family_parts.cpp app/registry/mc1/mc1_parts.h
                 "the registration frame names a family")

run_check(rc text)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the restored copy fails the check:\n${text}")
endif()
