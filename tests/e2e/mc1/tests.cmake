# The mc1 family's end-to-end tests (paths relative to tests/).
cambench_add_e2e_test(tst_e2e_mc1 e2e/mc1/tst_e2e_mc1.cpp)
