//! LeadWheelController::set_path, kept apart from the control law (lead_wheel_controller.cpp).

#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/controller/path_swap.hpp"

namespace smoothsteer {

Status LeadWheelController::set_path(std::shared_ptr<const Path> path) noexcept {
  // Only the reference changes: the chain (delta_1..delta_n) is the controller's own state and
  // the command is a function of it, so keeping it keeps the command continuous; the sliding
  // law then steers the chain towards the new path within the same bounds (paper Sec. II).
  return swap_path(path_, path, rear_hint_, front_hint_, lead_hint_);
}

}  // namespace smoothsteer
