# End-to-end runs of the real cambench-cli against the real cambench-sim
# (paths relative to tests/).

# The end-to-end tests start both executables as subprocesses; what they
# share to do so is compiled once.
add_library(cambench_e2e_support OBJECT e2e/sim_process.h e2e/sim_process.cpp e2e/e2e_support.h
            e2e/e2e_support.cpp e2e/test_pace.h e2e/test_pace.cpp)
target_link_libraries(cambench_e2e_support PRIVATE cambench_model cambench_child_process Qt6::Test)
target_compile_definitions(cambench_e2e_support PRIVATE
  CAMBENCH_SIM_EXE="$<TARGET_FILE:cambench-sim>"
  CAMBENCH_CLI_EXE="$<TARGET_FILE:cambench-cli>")
function(cambench_add_e2e_test name)
  cambench_add_test(${name} SOURCES ${ARGN} $<TARGET_OBJECTS:cambench_e2e_support>
                    LIBS cambench_model cambench_child_process)
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR})
  target_compile_definitions(${name} PRIVATE
    CAMBENCH_SIM_EXE="$<TARGET_FILE:cambench-sim>"
    CAMBENCH_CLI_EXE="$<TARGET_FILE:cambench-cli>")
  add_dependencies(${name} cambench-sim cambench-cli)
  # The longest tests (each runs programs over simulated lines): CTest
  # starts them first, so that the short ones fill in beside them rather
  # than one of these running alone at the end (CI runs the tests on a
  # fresh tree, without CTest's record of their times).
  set_tests_properties(${name} PROPERTIES COST 100)
endfunction()

cambench_add_e2e_test(tst_e2e_cli e2e/tst_e2e_cli.cpp)
# `cambench --help` is run there too (it must not need a display) when the
# desktop application is built; the fuzz build leaves it out.
if(TARGET cambench)
  target_compile_definitions(tst_e2e_cli PRIVATE CAMBENCH_GUI_EXE="$<TARGET_FILE:cambench>")
  add_dependencies(tst_e2e_cli cambench)
endif()
# The same suite over the Cam-BUS (its protocol rows and its own cases) as a
# test of its own: every cli run joins the simulated bus (an
# initialisation phase), which under the sanitizers takes longer than the
# point-to-point rows all together.
add_test(NAME tst_e2e_cli_cambus COMMAND tst_e2e_cli
  infoPrintsIdentityAndCapacities infoJsonIsAnObject camsEditRoundTrip
  camsWriteRejectsOverlapAndLeavesDeviceUntouched deadTimesRoundTrip settingsChangeOneValue
  plcRoundTrip camBusScanListsEveryUser camBusDeviceOptionReachesThatDevice
  camBusBackupRestoreVerify)
cambench_bound_test(tst_e2e_cli_cambus 1200 ENVIRONMENT CAMBENCH_E2E_CAMBUS=1)
cambench_add_e2e_test(tst_e2e_faults e2e/tst_e2e_faults.cpp)
cambench_add_e2e_test(tst_e2e_line e2e/tst_e2e_line.cpp)
cambench_add_e2e_test(tst_e2e_recovery e2e/tst_e2e_recovery.cpp)
cambench_add_e2e_test(tst_e2e_short e2e/tst_e2e_short.cpp)
cambench_add_e2e_test(tst_e2e_diff e2e/tst_e2e_diff.cpp)
cambench_add_e2e_test(tst_e2e_machine e2e/tst_e2e_machine.cpp)
# Issue 35, item 8: swapped ports, a restore goes only to its own device.
cambench_add_e2e_test(tst_e2e_machine_identity e2e/tst_e2e_machine_identity.cpp)
# cambench-sim --machine: every device of a machine file, and its shaft.
cambench_add_e2e_test(tst_e2e_sim_machine e2e/tst_e2e_sim_machine.cpp)
target_compile_definitions(tst_e2e_sim_machine PRIVATE
  CAMBENCH_DEMO_MACHINE="${PROJECT_SOURCE_DIR}/docs/demo-machine.json")
# A CamCon, an MC200 and a Compax3 on three ptys, taken at once.
cambench_add_e2e_test(tst_e2e_machine_families e2e/tst_e2e_machine_families.cpp)
# Issue 36: backups a person reads, differences in each family's terms,
# the manifest's who, why and with what, the safety copies beside.
cambench_add_e2e_test(tst_e2e_machine_readable e2e/tst_e2e_machine_readable.cpp)
# Issue 37: a machine's history in a git archive (versions, release, watch).
cambench_add_e2e_test(tst_e2e_machine_history e2e/tst_e2e_machine_history.cpp)
cambench_add_e2e_test(tst_e2e_check e2e/tst_e2e_check.cpp)
# Every command line of README.md's code blocks, read from it when it runs.
cambench_add_e2e_test(tst_e2e_readme e2e/tst_e2e_readme.cpp)
target_compile_definitions(tst_e2e_readme PRIVATE
  CAMBENCH_README="${PROJECT_SOURCE_DIR}/README.md" CAMBENCH_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
# A test that dies (aborted, killed) takes its simulator with it.
cambench_add_e2e_test(tst_e2e_cleanup e2e/tst_e2e_cleanup.cpp)
# Each family's tests of this area, listed in its folder (tests/e2e/<family>/).
cambench_include_family_lists(${CMAKE_CURRENT_LIST_DIR} tests.cmake)
