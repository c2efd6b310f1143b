# AddressSanitizer + UndefinedBehaviorSanitizer for the whole tree (CI builds the
# tests once with this on). Recovery is off so any report fails the test.
if(CAMBENCH_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
  # Line tables are all a sanitizer report needs; full debug information in
  # every one of the ~75 statically linked test programs came to 11 GB and
  # filled CI's disk. -g1 plus compressed sections keeps it near 1 GB.
  add_compile_options(-g1 -gz)
  add_link_options(-gz)
endif()
