# Issue 38, item 4: the fake family, built once for every test that hosts
# it (here and the shell's GUI tests in tests/ui/shell/).
if(CAMBENCH_GUI AND TARGET cambench_cli_front)
  add_library(cambench_test_fake_family STATIC
    family/fake_family.cpp family/fake_family.h family/fake_backup.cpp family/fake_backup.h)
  target_link_libraries(cambench_test_fake_family
    PUBLIC cambench_ui cambench_gui_registry cambench_sim cambench_cli_front)
endif()

# Issue 13, point 6: a family registered by the test alone, hosted by the
# shell's GUI and CLI front (paths relative to tests/).
if(CAMBENCH_GUI AND TARGET cambench_cli_front)
  cambench_add_test(tst_fake_family
    SOURCES family/tst_fake_family.cpp $<TARGET_OBJECTS:cambench_test_gui_check>
    LIBS cambench_ui cambench_gui_registry cambench_test_fake_family)
  # It counts the files outside tests/family/ that name the fake family.
  target_compile_definitions(tst_fake_family PRIVATE CAMBENCH_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endif()

# Issue 27: the shell's STOP on every page, its key, ahead of a long job;
# none for a CamCon; quitting while something moves asks.
if(CAMBENCH_GUI AND TARGET cambench_cli_front)
  cambench_add_test(tst_motion_stop
    SOURCES family/tst_motion_stop.cpp $<TARGET_OBJECTS:cambench_test_gui_check>
            ui/shell/shell_fixture.h
    LIBS cambench_ui cambench_gui_registry cambench_test_fake_family)
endif()

# Issue 31, item 1: the startup check names a family lacking a part.
cambench_add_test(tst_family_parts SOURCES family/tst_family_parts.cpp)

# Issue 38, item 1: a second test family whose protocol has an option of
# its own, taken by the command line, a machine file and the connection
# page; and no option or protocol of a family named in the shell.
if(CAMBENCH_GUI AND TARGET cambench_cli_front)
  cambench_add_test(tst_protocol_options
    SOURCES family/tst_protocol_options.cpp family/slotted_family.h family/slotted_family.cpp
            $<TARGET_OBJECTS:cambench_test_gui_check>
    LIBS cambench_ui cambench_gui_registry cambench_test_fake_family)
  target_compile_definitions(tst_protocol_options PRIVATE CAMBENCH_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endif()
