# The compax3 family's GUI tests (paths relative to tests/).
cambench_add_test(ui_compax3_pages_test SOURCES ui/register_widgets.cpp ui/compax3/tst_compax3_pages.cpp ui/shell/shell_fixture.h LIBS cambench_ui cambench_gui_registry)
