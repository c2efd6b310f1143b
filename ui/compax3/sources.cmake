# The Compax3 family's pages (Objects, Status, Motion, Watch, Parameters),
# its part of the window and its protocols' settings widget.
target_sources(cambench_ui PRIVATE
  compax3/compax3_page.h
  compax3/compax3_page.cpp
  compax3/compax3_report.h
  compax3/compax3_report.cpp
  compax3/compax3_gui.h
  compax3/compax3_gui.cpp
  compax3/compax3_object_model.h
  compax3/compax3_object_model.cpp
  compax3/compax3_objects_page.h
  compax3/compax3_objects_page.cpp
  compax3/compax3_status_page.h
  compax3/compax3_status_page.cpp
  compax3/compax3_motion_page.h
  compax3/compax3_motion_page.cpp
  compax3/compax3_watch_page.h
  compax3/compax3_watch_page.cpp
  compax3/compax3_parameters_page.h
  compax3/compax3_parameters_page.cpp
  compax3/compax3_window.h
  compax3/compax3_window.cpp
  compax3/compax3_tour.cpp
)
