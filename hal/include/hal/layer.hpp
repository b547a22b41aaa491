// hal/layer.hpp: devices that forward to another device (the validation layer, fault injection)
// say so, so that backend-specific calls (presentation, the recording HAL's reports) can reach the
// backend under any stack of layers.
#pragma once

#include "hal/device.hpp"

namespace hal {

class DeviceLayer {
 public:
  virtual ~DeviceLayer() = default;
  virtual Device& inner() = 0;
};

// The backend under every layer of `device` (`device` itself when it is not a layer).
inline Device& backend_of(Device& device) {
  Device* d = &device;
  while (auto* layer = dynamic_cast<DeviceLayer*>(d)) d = &layer->inner();
  return *d;
}

}  // namespace hal
