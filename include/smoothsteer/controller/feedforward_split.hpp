#pragma once
//! \file feedforward_split.hpp
//! Stage 4 of LeadWheelController::compute_command(), once per sub-step: the lead curvature
//! kappa_n = kappa_ff + kappa_sw split between the rate-limited feedforward and the switching
//! part (docs/feedforward.md). The switching law itself is dubins_switching_law.hpp.

#include <algorithm>
#include <cmath>

namespace smoothsteer {

//! kappa_ff moves towards its target by at most `max_step` (L_ff times the sub-step), and stays
//! within +-bound (the split the certificate assumes). Returns the clamped target.
inline double step_feedforward(double& feedforward, double target, double bound,
                               double max_step) noexcept {
  const double wanted = std::clamp(target, -bound, bound);
  feedforward += std::clamp(wanted - feedforward, -max_step, max_step);
  return wanted;
}

//! The switching part kappa_sw around the law's curvature `law` (authority law_bound):
//! - catch-up (FeedforwardParameters::catch_up): up to `catch_up` of what the rate limit still
//!   holds kappa_ff back from `wanted`, faded out as the law saturates, so that
//!   |kappa_sw| <= kbar_sw and a saturated law keeps its full authority;
//! - the matched disturbance of the tests;
//! - the friction guard: |kappa_ff + kappa_sw| <= guard where kappa_sw can reach it; while
//!   kappa_ff still ramps down into the guard, kappa_sw pulls with its full authority.
inline double switching_curvature(double law, double law_bound, double wanted, double feedforward,
                                  double catch_up, double matched_disturbance, double guard,
                                  double lead_bound) noexcept {
  const double fade = law_bound > 0.0 ? 1.0 - std::min(1.0, std::abs(law) / law_bound) : 0.0;
  double switching =
      law + fade * std::clamp(wanted - feedforward, -catch_up, catch_up) + matched_disturbance;
  if (guard < lead_bound) {
    const double low = std::max(-guard - feedforward, -law_bound);
    const double high = std::min(guard - feedforward, law_bound);
    switching = low <= high ? std::clamp(switching, low, high)
                            : (feedforward > 0.0 ? -law_bound : law_bound);
  }
  return switching;
}

}  // namespace smoothsteer
