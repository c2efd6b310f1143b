# The camcon family's GUI tests (paths relative to tests/).
cambench_add_test(ui_cambus_view_test SOURCES ui/register_widgets.cpp ui/camcon/tst_cambus_view.cpp ui/shell/shell_fixture.h LIBS cambench_ui cambench_gui_registry)
cambench_add_test(ui_workspace_sections_test SOURCES ui/register_widgets.cpp ui/camcon/tst_workspace_sections.cpp LIBS cambench_ui cambench_gui_registry)
