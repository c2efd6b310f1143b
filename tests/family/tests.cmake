# Issue 13, point 6: a family registered by the test alone, hosted by the
# shell's GUI and CLI front (paths relative to tests/).
if(CAMBENCH_GUI AND TARGET cambench_cli_front)
  cambench_add_test(tst_fake_family
    SOURCES family/tst_fake_family.cpp family/fake_family.h family/fake_family.cpp
            ui/register_widgets.cpp
    LIBS cambench_ui cambench_gui_registry cambench_sim cambench_cli_front)
endif()
