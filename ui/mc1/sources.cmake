# The MC-1 family's pages (Variables, Flags & I/O, Program, Axes, Memory,
# Trend), its part of the window and its protocol's settings widget.
target_sources(cambench_ui PRIVATE
  mc1/mc1_page.h
  mc1/mc1_watch_model.h
  mc1/mc1_watch_model.cpp
  mc1/mc1_value_delegate.h
  mc1/mc1_value_delegate.cpp
  mc1/mc1_settings.h
  mc1/mc1_settings.cpp
  mc1/mc1_variables_page.h
  mc1/mc1_variables_page.cpp
  mc1/mc1_points_page.h
  mc1/mc1_points_page.cpp
  mc1/mc1_program_page.h
  mc1/mc1_program_page.cpp
  mc1/mc1_axes_page.h
  mc1/mc1_axes_page.cpp
  mc1/mc1_axis_parameters_box.h
  mc1/mc1_axis_parameters_box.cpp
  mc1/mc1_memory_page.h
  mc1/mc1_memory_page.cpp
  mc1/mc1_trend_page.h
  mc1/mc1_trend_page.cpp
  mc1/mc1_report.h
  mc1/mc1_report.cpp
  mc1/mc1_gui.h
  mc1/mc1_gui.cpp
  mc1/mc1_window.h
  mc1/mc1_window.cpp
  mc1/mc1_tour.cpp
  mc1/protocols/mc1_settings_widget.h
  mc1/protocols/mc1_settings_widget.cpp
)
