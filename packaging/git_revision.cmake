# Writes cambench_version.h with the project version and the git revision of
# the source tree. Run in script mode on every build (see CMakeLists.txt here)
# and once at configure time; configure_file() leaves the header untouched when
# the text is the same, so an unchanged revision recompiles nothing.
#
# Inputs: SOURCE_DIR, VERSION, TEMPLATE, OUTPUT.

set(CAMBENCH_VERSION_NUMBER "${VERSION}")
set(CAMBENCH_REVISION "unknown")
find_program(CAMBENCH_GIT git)
if(CAMBENCH_GIT)
  execute_process(
    COMMAND "${CAMBENCH_GIT}" -C "${SOURCE_DIR}" rev-parse --short HEAD
    RESULT_VARIABLE head_result
    OUTPUT_VARIABLE head
    OUTPUT_STRIP_TRAILING_WHITESPACE
    ERROR_QUIET)
  # A tarball unpacked inside some other checkout must not take that one's hash.
  execute_process(
    COMMAND "${CAMBENCH_GIT}" -C "${SOURCE_DIR}" rev-parse --show-toplevel
    OUTPUT_VARIABLE toplevel
    OUTPUT_STRIP_TRAILING_WHITESPACE
    ERROR_QUIET)
  file(REAL_PATH "${SOURCE_DIR}" source_real)
  if(toplevel)
    file(REAL_PATH "${toplevel}" toplevel)
  endif()
  if(head_result EQUAL 0 AND head AND toplevel STREQUAL source_real)
    set(CAMBENCH_REVISION "${head}")
    # Tracked files only: build directories and other untracked files are no
    # change to the sources. --no-optional-locks: never write the index here.
    execute_process(
      COMMAND "${CAMBENCH_GIT}" --no-optional-locks -C "${SOURCE_DIR}"
              status --porcelain --untracked-files=no
      RESULT_VARIABLE status_result
      OUTPUT_VARIABLE changes
      ERROR_QUIET)
    if(status_result EQUAL 0 AND NOT changes STREQUAL "")
      string(APPEND CAMBENCH_REVISION "+dirty")
    endif()
  endif()
endif()

configure_file("${TEMPLATE}" "${OUTPUT}" @ONLY)
