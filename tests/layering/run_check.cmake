# What the planting scripts share: run_check(RC TEXT) runs the check CHECK
# over the scratch tree SCRATCH and hands back its exit code and its output.
include_guard(GLOBAL)

function(run_check out_rc out_text)
  execute_process(COMMAND ${CMAKE_COMMAND} -DROOT=${SCRATCH} -P ${CHECK}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(${out_rc} ${rc} PARENT_SCOPE)
  set(${out_text} "${out}${err}" PARENT_SCOPE)
endfunction()

# Fails unless the untouched scratch tree passes the check, so that a
# failure after planting is the planted line's doing.
function(expect_untouched_passes)
  run_check(rc text)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the untouched copy of the tree fails the check:\n${text}")
  endif()
endfunction()

# Appends LINE to FILE (a path under SCRATCH), runs the check and restores
# the file; hands back the check's exit code, its output and the number of
# the planted line.
function(run_check_planted file line out_rc out_text out_number)
  set(path "${SCRATCH}/${file}")
  file(READ "${path}" original)
  string(REGEX MATCHALL "\n" newlines "${original}")
  list(LENGTH newlines count)
  math(EXPR number "${count} + 1")
  file(APPEND "${path}" "${line}\n")
  run_check(rc text)
  file(WRITE "${path}" "${original}")
  set(${out_rc} ${rc} PARENT_SCOPE)
  set(${out_text} "${text}" PARENT_SCOPE)
  set(${out_number} ${number} PARENT_SCOPE)
endfunction()

# Judges a planted violation at WHERE ("file:line"): the check must have
# failed (RC) and named it (its output TEXT matches PATTERN).
function(expect_caught rc text pattern where why)
  if(rc EQUAL 0)
    message(SEND_ERROR "not caught (${why}): ${where}")
  elseif(NOT text MATCHES "${pattern}")
    message(SEND_ERROR "caught, but not as ${where} (${why}):\n${text}")
  else()
    message(STATUS "caught (${why}): ${where}")
  endif()
endfunction()
