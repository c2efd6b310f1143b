# The MICRO DESIGN MC100/MC200 (MC-1) family (announced; its protocol comes with its own issue).
target_sources(cambench_comm PRIVATE
  mc1/mc1_family.h
  mc1/mc1_family.cpp
)
