# The Parker Compax3 family (announced; its protocol comes with its own issue).
target_sources(cambench_comm PRIVATE
  compax3/compax3_family.h
  compax3/compax3_family.cpp
)
