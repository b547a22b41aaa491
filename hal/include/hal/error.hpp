// hal/error.hpp: the one error type every HAL call throws.
//
// Contract: a HAL call either succeeds or throws hal::Error; it never aborts and never returns a
// silent null handle. The message names the object (by its debug name) and the cause, so that a
// user reading only the message knows what to fix.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace hal {

enum class ErrorKind {
  InvalidDescriptor,  // zero or absurd size, unknown format, bad usage combination
  Unsupported,        // the device lacks a format, feature or extension that was asked for
  OutOfMemory,        // host or device allocation failed
  DeviceLost,         // the device stopped; every later call fails too
  BindingMismatch,    // C++ binding names or kinds do not match the shader's reflection
  InvalidHandle,      // a destroyed or never-created handle was passed
  InvalidUsage,       // a call breaks the contract (wrong state, unbound binding, ...)
  NoDevice,           // no usable device or driver was found
  Backend,            // any other failure reported by the backend API
};

std::string_view to_string(ErrorKind kind);

class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, std::string_view object, std::string_view cause)
      : std::runtime_error(format(kind, object, cause)), kind_(kind), object_(object) {}

  ErrorKind kind() const { return kind_; }
  // Debug name of the object the error is about ("" when it is about the device as a whole).
  const std::string& object() const { return object_; }

 private:
  static std::string format(ErrorKind kind, std::string_view object, std::string_view cause) {
    std::string message(to_string(kind));
    if (!object.empty()) message.append(": '").append(object).append("'");
    message.append(": ").append(cause);
    return message;
  }
  ErrorKind kind_;
  std::string object_;
};

inline std::string_view to_string(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::InvalidDescriptor: return "invalid descriptor";
    case ErrorKind::Unsupported: return "unsupported";
    case ErrorKind::OutOfMemory: return "out of memory";
    case ErrorKind::DeviceLost: return "device lost";
    case ErrorKind::BindingMismatch: return "binding mismatch";
    case ErrorKind::InvalidHandle: return "invalid handle";
    case ErrorKind::InvalidUsage: return "invalid usage";
    case ErrorKind::NoDevice: return "no device";
    case ErrorKind::Backend: return "backend error";
  }
  return "error";
}

}  // namespace hal
