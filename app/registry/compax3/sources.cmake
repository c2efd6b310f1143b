# The Parker Compax3 family's registration: every part of it named in one
# place (paths relative to app/; compiled into each program's kind of
# registration, see app/registry/sources.cmake).
list(APPEND CAMBENCH_FAMILY_PARTS
  registry/compax3/compax3_parts.h
  registry/compax3/compax3_parts.cpp
)
