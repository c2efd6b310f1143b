# The mc1 family's model tests (paths relative to tests/).
cambench_add_test(tst_mc1_backup_file SOURCES model/mc1/tst_mc1_backup_file.cpp LIBS cambench_model)
cambench_add_test(tst_mc1_project_file SOURCES model/mc1/tst_mc1_project_file.cpp LIBS cambench_model)
