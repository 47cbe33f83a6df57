#pragma once
//! \file status.hpp
//! Result codes of the real-time calls. Real-time calls never throw; they return a Status.

namespace smoothsteer {

enum class Status {
  ok = 0,                //!< output is valid
  invalid_input = -1,    //!< NaN/inf or out of ControllerInputRange, or a non-positive period
  not_configured = -2,   //!< the controller has no path
  numerical_error = -3,  //!< an internal value became non-finite; the state was reset
  unsupported = -4,      //!< the controller does not implement this call
};

//! Human-readable name of a status, for logs.
constexpr const char* to_string(Status status) noexcept {
  switch (status) {
    case Status::ok:
      return "ok";
    case Status::invalid_input:
      return "invalid_input";
    case Status::not_configured:
      return "not_configured";
    case Status::numerical_error:
      return "numerical_error";
    case Status::unsupported:
      return "unsupported";
  }
  return "unknown";
}

}  // namespace smoothsteer
