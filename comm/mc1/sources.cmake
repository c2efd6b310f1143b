# The MICRO DESIGN MC100/MC200 (MC-1) family: its protocol core (telegrams of
# the four variants, answers, address arithmetic); the device, simulator and
# pages come with issue 14's next steps.
target_sources(cambench_comm PRIVATE
  mc1/mc1_family.h
  mc1/mc1_family.cpp
  mc1/mc1_variant.h
  mc1/mc1_variant.cpp
  mc1/mc1_telegram.h
  mc1/mc1_telegram.cpp
  mc1/mc1_catalogue.h
  mc1/mc1_catalogue.cpp
  mc1/mc1_address.h
  mc1/mc1_address.cpp
  mc1/mc1_ascii.h
  mc1/mc1_ascii.cpp
  mc1/mc1_backend.h
  mc1/mc1_backend.cpp
  mc1/mc1_link.h
  mc1/mc1_link.cpp
)
