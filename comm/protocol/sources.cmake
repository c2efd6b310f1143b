target_sources(cambench_comm PRIVATE
  protocol/frame.h
  protocol/stream_decoder.h
  protocol/fields.h
  protocol/catalogue.h
  protocol/command_codec.h
  protocol/device_errors.h
)
