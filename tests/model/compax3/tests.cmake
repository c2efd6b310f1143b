# The compax3 family's model tests (paths relative to tests/).
cambench_add_test(tst_compax3_syntax SOURCES model/compax3/tst_compax3_syntax.cpp LIBS cambench_comm)
# Also under a German C locale: numbers must still go out with a point.
cambench_bound_test(tst_compax3_syntax 300 ENVIRONMENT "LC_ALL=de_DE.UTF-8;LANG=de_DE.UTF-8")
