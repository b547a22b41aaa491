// Registers the recording HAL: it executes nothing, so only ordering tests run on it; every
// report it makes fails the test.
#include "backends.hpp"
#include "hal_record/record_device.hpp"

namespace {

const conformance::Register record({"record",
                                    [](std::vector<std::string>&) -> std::unique_ptr<hal::Device> {
                                      return std::make_unique<hal::record::RecordDevice>();
                                    },
                                    false,
                                    [](hal::Device& device, std::vector<std::string>& messages) {
                                      for (const auto& r : static_cast<hal::record::RecordDevice&>(device).reports())
                                        messages.push_back(r.message);
                                    }});

}  // namespace
