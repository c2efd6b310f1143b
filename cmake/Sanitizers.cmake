# AddressSanitizer + UndefinedBehaviorSanitizer for the whole tree (CI builds the
# tests once with this on). Recovery is off so any report fails the test.
if(CAMBENCH_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
