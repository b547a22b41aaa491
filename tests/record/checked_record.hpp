// A recording device behind the validation layer, as every device in the project is used:
// contract errors throw from the layer, ordering hazards are reported by `record`.
#pragma once

#include <memory>

#include "hal/layer.hpp"
#include "hal/validate.hpp"
#include "hal_record/record_device.hpp"

struct CheckedRecord {
  explicit CheckedRecord(hal::record::RecordOptions options = {})
      : checked(hal::validate::wrap(std::make_unique<hal::record::RecordDevice>(options))),
        record(static_cast<hal::record::RecordDevice&>(hal::backend_of(*checked))),
        device(*checked) {}
  std::unique_ptr<hal::Device> checked;
  hal::record::RecordDevice& record;
  hal::Device& device;
};
