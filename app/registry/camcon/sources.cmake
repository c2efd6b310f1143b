# The Digitronic CamCon family's registration: every part of it named in one
# place (paths relative to app/; compiled into each program's kind of
# registration, see app/registry/sources.cmake).
list(APPEND CAMBENCH_FAMILY_PARTS
  registry/camcon/camcon_parts.h
  registry/camcon/camcon_parts.cpp
)
