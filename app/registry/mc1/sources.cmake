# The MICRO DESIGN MC-1 family's registration: every part of it named in one
# place (paths relative to app/; compiled into each program's kind of
# registration, see app/registry/sources.cmake).
list(APPEND CAMBENCH_FAMILY_PARTS
  registry/mc1/mc1_parts.h
  registry/mc1/mc1_parts.cpp
)
