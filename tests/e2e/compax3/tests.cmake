# The compax3 family's end-to-end tests (paths relative to tests/).
cambench_add_e2e_test(tst_e2e_compax3 e2e/compax3/tst_e2e_compax3.cpp)
