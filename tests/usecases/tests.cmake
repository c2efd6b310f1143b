# Each family's tests of this area, listed in its folder (tests/usecases/<family>/).
cambench_include_family_lists(${CMAKE_CURRENT_LIST_DIR} tests.cmake)
