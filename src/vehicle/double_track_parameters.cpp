#include "smoothsteer/vehicle/double_track_parameters.hpp"

#include <cmath>
#include <limits>

namespace smoothsteer {
namespace {

bool share(double value) noexcept {
  return std::isfinite(value) && value >= 0.0 && value <= 1.0;
}

bool non_negative(double value) noexcept {
  return std::isfinite(value) && value >= 0.0;
}

// Physical ranges of the body's roll, as ratios that hold from a model car to a truck. Measured
// cars (Heydinger et al., "Measured Vehicle Inertial Parameters - NHTSA's Data Through November
// 1998", SAE 1999-01-1336; the CommonRoad sets of vehicles/) have a roll radius of gyration
// sqrt(I_xx / m) of 0.3-0.4 track widths, a roll frequency sqrt(K_phi / I_xx) / 2 pi of 1.5-3 Hz
// (race cars up to about 5 Hz: Milliken and Milliken, Race Car Vehicle Dynamics, ch. 16) and a
// roll damping ratio D_phi / (2 sqrt(K_phi I_xx)) of 0.2-0.7 (Gillespie, Fundamentals of Vehicle
// Dynamics, ch. 5). The bounds leave a wide margin; beyond them the roll mode is so fast or so
// stiff that the plant's integrator takes minutes per simulated second.
constexpr double min_roll_gyration_per_track = 0.1;
constexpr double max_roll_gyration_per_track = 1.0;
constexpr double max_roll_frequency_hz = 10.0;
constexpr double max_roll_damping_ratio = 5.0;
constexpr double two_pi = 6.283185307179586;

}  // namespace

std::optional<Violation> DoubleTrackParameters::first_violation(const char* owner,
                                                                const char* prefix, double mass_kg,
                                                                double gravity_mps2,
                                                                double roll_arm_m) const noexcept {
  auto bad = [owner, prefix](const char* field, double value, const char* rule,
                             double reference = std::numeric_limits<double>::quiet_NaN()) {
    return Violation{owner, prefix, field, value, rule, reference};
  };
  if (!positive_finite(front_track_m) || front_track_m > 5.0) {
    return bad("front_track_m", front_track_m, "must be in (0, 5] m");
  }
  if (!positive_finite(rear_track_m) || rear_track_m > 5.0) {
    return bad("rear_track_m", rear_track_m, "must be in (0, 5] m");
  }
  if (!positive_finite(roll_inertia_kgm2)) {
    return bad("roll_inertia_kgm2", roll_inertia_kgm2, "must be finite and > 0");
  }
  if (!non_negative(front_roll_stiffness_nmprad)) {
    return bad("front_roll_stiffness_nmprad", front_roll_stiffness_nmprad,
               "must be finite and >= 0");
  }
  if (!non_negative(rear_roll_stiffness_nmprad)) {
    return bad("rear_roll_stiffness_nmprad", rear_roll_stiffness_nmprad, "must be finite and >= 0");
  }
  // The body rolls about an axis on the ground: gravity's moment m g h phi tips it over unless
  // the springs carry more (Rajamani, roll dynamics: the roll equation's stiffness K_phi - m g h).
  const double tipping = mass_kg * gravity_mps2 * roll_arm_m;
  if (!(roll_stiffness_nmprad() > tipping)) {
    return bad("rear_roll_stiffness_nmprad", rear_roll_stiffness_nmprad,
               "gives a roll stiffness front + rear <= m g h (the body tips over on its "
               "springs); m g h =",
               tipping);
  }
  if (!non_negative(front_roll_damping_nmsprad)) {
    return bad("front_roll_damping_nmsprad", front_roll_damping_nmsprad, "must be finite and >= 0");
  }
  if (!non_negative(rear_roll_damping_nmsprad)) {
    return bad("rear_roll_damping_nmsprad", rear_roll_damping_nmsprad, "must be finite and >= 0");
  }
  if (!(front_roll_damping_nmsprad + rear_roll_damping_nmsprad > 0.0)) {
    return bad("rear_roll_damping_nmsprad", rear_roll_damping_nmsprad,
               "must make the roll damping front + rear > 0 (an undamped roll mode)");
  }
  const double track = 0.5 * (front_track_m + rear_track_m);
  const double gyration = std::sqrt(roll_inertia_kgm2 / mass_kg);
  if (!(gyration >= min_roll_gyration_per_track * track &&
        gyration <= max_roll_gyration_per_track * track)) {
    return bad("roll_inertia_kgm2", roll_inertia_kgm2,
               "gives a roll radius of gyration sqrt(I_xx / m) outside [0.1, 1] mean track "
               "widths (cars: 0.3-0.4); sqrt(I_xx / m) [m] =",
               gyration);
  }
  const double stiffness = roll_stiffness_nmprad();
  const double frequency_hz = std::sqrt(stiffness / roll_inertia_kgm2) / two_pi;
  if (!(frequency_hz <= max_roll_frequency_hz)) {
    const bool front = front_roll_stiffness_nmprad > rear_roll_stiffness_nmprad;
    return bad(front ? "front_roll_stiffness_nmprad" : "rear_roll_stiffness_nmprad",
               front ? front_roll_stiffness_nmprad : rear_roll_stiffness_nmprad,
               "gives a roll frequency sqrt((front + rear) / I_xx) / 2 pi above 10 Hz (cars: "
               "1.5-3 Hz); frequency [Hz] =",
               frequency_hz);
  }
  const double damping_ratio = (front_roll_damping_nmsprad + rear_roll_damping_nmsprad) /
                               (2.0 * std::sqrt(stiffness * roll_inertia_kgm2));
  if (!(damping_ratio <= max_roll_damping_ratio)) {
    const bool front = front_roll_damping_nmsprad > rear_roll_damping_nmsprad;
    return bad(front ? "front_roll_damping_nmsprad" : "rear_roll_damping_nmsprad",
               front ? front_roll_damping_nmsprad : rear_roll_damping_nmsprad,
               "gives a roll damping ratio (front + rear) / (2 sqrt(K_phi I_xx)) above 5 (cars: "
               "0.2-0.7); ratio =",
               damping_ratio);
  }
  if (!share(drive_share_front)) {
    return bad("drive_share_front", drive_share_front, "must be in [0, 1]");
  }
  if (!share(brake_share_front)) {
    return bad("brake_share_front", brake_share_front, "must be in [0, 1]");
  }
  if (!positive_finite(longitudinal_friction_mu) || longitudinal_friction_mu > 3.0) {
    return bad("longitudinal_friction_mu", longitudinal_friction_mu, "must be in (0, 3]");
  }
  // mu (1 + s dfz) must stay positive up to three times the static load (dfz = 2).
  if (!std::isfinite(friction_load_sensitivity) || friction_load_sensitivity <= -0.5 ||
      friction_load_sensitivity > 0.5) {
    return bad("friction_load_sensitivity", friction_load_sensitivity, "must be in (-0.5, 0.5]");
  }
  if (!share(ackermann_share)) {
    return bad("ackermann_share", ackermann_share, "must be in [0, 1]");
  }
  return std::nullopt;
}

}  // namespace smoothsteer
