// hal/validate.hpp: the one place that checks the HAL contract.
//
// wrap() puts a checking layer in front of any backend (as NVRHI's validation device does): every
// call is checked against the rules written in hal/device.hpp, hal/command_list.hpp and
// hal/types.hpp before it is forwarded, and a call that breaks one throws hal::Error naming the
// objects involved. Backends therefore check only what their own API needs (device limits, format
// support, allocation failures) and may assume the calls they receive are valid.
//
// What it checks: handles (never created, destroyed), descriptors (sizes, usages, formats, counts),
// binding sets against the shader reflection (names, kinds, twice-bound, storage-image formats,
// usages, storage range), dispatches (set made for the pipeline's shader, every binding bound and
// alive, uniform size, non-zero workgroups), barrier states per resource kind, copies and clears
// (usages, ranges, sizes), acceleration-structure builds, timer regions, host transfers, and the
// command-list lifecycle (labels balanced at submit, no recording after submit without reset, no
// reset or resubmit while the device may still execute it). Ordering hazards (missing barriers)
// are not checked here: the recording HAL (hal_record) finds those.
#pragma once

#include <memory>

#include "hal/device.hpp"

namespace hal::validate {

// A device that checks every call and forwards it to `inner`. Handles are `inner`'s own.
std::unique_ptr<Device> wrap(std::unique_ptr<Device> inner);

// True when a binding of `kind` can be bound to a resource of `resource` kind.
bool binding_accepts(BindingKind kind, ResourceKind resource);

}  // namespace hal::validate
