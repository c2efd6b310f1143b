cambench_add_test(tst_atomic_file SOURCES model/tst_atomic_file.cpp LIBS cambench_model)
cambench_add_test(tst_walked_list SOURCES model/tst_walked_list.cpp LIBS cambench_model)
cambench_add_test(tst_machine_file SOURCES model/tst_machine_file.cpp LIBS cambench_model)
cambench_add_test(tst_device_identity SOURCES model/tst_device_identity.cpp LIBS cambench_model)
cambench_add_test(tst_machine_archive SOURCES model/tst_machine_archive.cpp LIBS cambench_model)
# Each family's tests of this area, listed in its folder (tests/model/<family>/).
cambench_include_family_lists(${CMAKE_CURRENT_LIST_DIR} tests.cmake)
