// The feedforward route of the tuner (docs/tuning.md, "Feedforward route"): at each speed the
// largest switching authority kbar_sw such that the certificate of steering_certificate.hpp meets
// the vehicle's rate and acceleration limits, with the feedforward covering the path.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "smoothsteer/controller/steering_certificate.hpp"
#include "smoothsteer/tuning/gain_schedule.hpp"
#include "smoothsteer/tuning/invariant_bounds.hpp"
#include "smoothsteer/tuning/path_demand.hpp"

namespace smoothsteer {
namespace {

constexpr int kLeadWheelbaseNodes = 48;  // lambda_l / lambda_veh in (0, 0.98] (O4)
constexpr int kBisections = 50;
constexpr double kCertificateSlack = 1e-9;

struct SpeedProblem {
  const VehicleLimits& vehicle;
  const TuningOptions& options;
  double speed = 0.0;
  double lead_wheelbase = 0.0;  //!< lambda_l (0 for n = 1)
  //! The curvature rate the feedforward should follow [1/m^2]; < 0: the options' path rate.
  double feedforward_rate_demand = -1.0;

  double rate_demand() const {
    return feedforward_rate_demand >= 0.0 ? feedforward_rate_demand
                                          : options.path_curvature_rate_bound;
  }

  ScheduleEntry entry(double feedforward_bound, double feedforward_rate,
                      double switching_bound) const {
    ScheduleEntry e;
    e.speed_mps = speed;
    e.lead_wheelbase_m = options.order == 2 ? lead_wheelbase : 0.0;
    e.lead_curvature_bound = feedforward_bound + switching_bound;
    e.feedforward_curvature_bound = feedforward_bound;
    e.feedforward_curvature_rate = feedforward_rate;
    e.k_rob = std::max(options.k_rob_floor, options.matched_disturbance_curvature /
                                                switching_bound * (1.0 + kCertificateSlack));
    return e;
  }
  //! Fills the certified maxima; false if they break a limit.
  bool certify(ScheduleEntry& e) const {
    const ControllerParameters p = schedule_entry_parameters(options, vehicle.wheelbase_m, e);
    if (!p.is_valid()) return false;
    const SteeringCertificate c = feedforward_certificate(p);
    e.fictive_wheelbase_m = p.chain.wheelbases_m[0];
    e.max_steering_angle_rad = c.steering_angle_rad;
    e.max_steering_rate_radps = c.rate_radps(speed);
    e.max_steering_acceleration_radps2 =
        options.order >= 2
            ? c.acceleration_radps2(speed, options.max_longitudinal_acceleration_mps2)
            : std::numeric_limits<double>::infinity();
    // No slack: the certified maxima never exceed the limits, not even by rounding.
    return e.max_steering_angle_rad <= vehicle.max_steering_angle_rad &&
           e.max_steering_rate_radps <= vehicle.max_steering_rate_radps &&
           (std::isinf(vehicle.max_steering_acceleration_radps2) ||
            e.max_steering_acceleration_radps2 <= vehicle.max_steering_acceleration_radps2);
  }
};

//! Largest kbar_n the angle limit (with the cornering constraint sum lambda_i^2 = lambda_veh^2,
//! eq. kappalmax corrected) and the friction limit (kbar_0 <= a_lat / v^2) allow.
double largest_lead_curvature(const VehicleLimits& vehicle, double speed) {
  const double l = vehicle.wheelbase_m;
  double bound = std::sin(vehicle.max_steering_angle_rad) / l;
  if (std::isfinite(vehicle.max_lateral_acceleration_mps2)) {
    const double rear = vehicle.max_lateral_acceleration_mps2 / (speed * speed);
    bound = std::min(bound, stationary_lead_curvature(rear, l * l));
  }
  return bound * (1.0 - 1e-9);
}

//! Largest x in [0, high] with ok(x), for ok monotone (true below a threshold).
template <class Ok>
double largest(double high, Ok&& ok) {
  if (ok(high)) return high;
  double low = 0.0;
  for (int i = 0; i < kBisections; ++i) {
    const double mid = 0.5 * (low + high);
    (ok(mid) ? low : high) = mid;
  }
  return low;
}

//! The i-th of `nodes` candidate lead wheelbases, i = 1..nodes.
double lead_wheelbase_node(const VehicleLimits& vehicle, int i, int nodes) {
  return vehicle.wheelbase_m * 0.98 * i / nodes;
}

//! The best entry for one lead wheelbase, or an entry with lead_curvature_bound 0 if none.
ScheduleEntry solve_node(const SpeedProblem& problem) {
  const TuningOptions& o = problem.options;
  const double total = largest_lead_curvature(problem.vehicle, problem.speed);
  const double feedforward_bound = std::min(o.feedforward_headroom * o.path_curvature_bound,
                                            total * (1.0 - o.switching_floor_share));
  const double tiny = total * 1e-6;
  // The rate budget of the feedforward alone (kbar_sw -> 0), then its share of it.
  double feedforward_rate = 0.0;
  if (feedforward_bound > 0.0) {
    const double budget = largest(1e3, [&](double rate) {
      ScheduleEntry e = problem.entry(feedforward_bound, rate, tiny);
      return problem.certify(e);
    });
    feedforward_rate = std::min(std::max(o.feedforward_rate_margin * problem.rate_demand(),
                                         feedforward_bound / o.feedforward_ramp_length_m),
                                o.feedforward_rate_share * budget);
  }
  const double switching = largest(total - feedforward_bound, [&](double bound) {
    if (bound <= 0.0) return true;
    ScheduleEntry e = problem.entry(feedforward_bound, feedforward_rate, bound);
    return problem.certify(e);
  });
  ScheduleEntry best =
      problem.entry(feedforward_bound, feedforward_rate, std::max(switching, tiny));
  if (!problem.certify(best) || switching <= tiny) best.lead_curvature_bound = 0.0;
  // Region label: which limit caps kbar_sw (angle/friction: region 1; rate; acceleration).
  if (best.lead_curvature_bound > 0.0) {
    const double slack = 1.0 - 1e-6;
    if (switching >= (total - feedforward_bound) * slack) {
      best.region = VelocityRegion::region1;
    } else if (best.max_steering_rate_radps >= problem.vehicle.max_steering_rate_radps * slack) {
      best.region = VelocityRegion::rate_only;
    } else {
      best.region = VelocityRegion::region4;
    }
  }
  return best;
}

[[noreturn]] void throw_infeasible(const SpeedProblem& problem, const ScheduleEntry& best) {
  const VehicleLimits& l = problem.vehicle;
  // Which limit binds: retry without it.
  std::string binding = "steering rate and acceleration";
  auto feasible_without = [&](bool rate, bool acceleration) {
    VehicleLimits relaxed = l;
    if (rate) relaxed.max_steering_rate_radps = 1e9;
    if (acceleration) relaxed.max_steering_acceleration_radps2 = 1e18;
    const SpeedProblem q{relaxed, problem.options, problem.speed, problem.lead_wheelbase};
    const ScheduleEntry e = solve_node(q);
    return e.lead_curvature_bound - e.feedforward_curvature_bound >=
           problem.options.min_lead_curvature_bound;
  };
  if (feasible_without(true, false))
    binding = "steering rate";
  else if (feasible_without(false, true))
    binding = "steering acceleration";
  std::ostringstream text;
  text.precision(6);
  text << "infeasible limits at v = " << problem.speed << " m/s: the " << binding << " limit (";
  if (binding != "steering acceleration") text << l.max_steering_rate_radps << " rad/s";
  if (binding == "steering rate and acceleration") text << ", ";
  if (binding != "steering rate") text << l.max_steering_acceleration_radps2 << " rad/s^2";
  text << ") binds: the largest certified switching authority kbar_sw is "
       << best.lead_curvature_bound - best.feedforward_curvature_bound
       << " 1/m < min_lead_curvature_bound = " << problem.options.min_lead_curvature_bound
       << " 1/m (feedforward kbar_ff = " << best.feedforward_curvature_bound
       << " 1/m, L_ff = " << best.feedforward_curvature_rate
       << " 1/m^2). Relax that limit, lower the top speed, or give the path's curvature rate.";
  throw InfeasibleLimits(text.str(), problem.speed, binding);
}

//! The feedforward route with the path's bounds of each speed: `at_speed[k]` are the options at
//! speeds_mps[k] (they differ in path_curvature_bound and path_curvature_rate_bound only).
GainSchedule feedforward_schedule(const VehicleLimits& vehicle, const TuningOptions& options,
                                  const std::vector<TuningOptions>& at_speed,
                                  const std::vector<double>& speeds_mps,
                                  const SpeedSolved& speed_solved) {
  check_schedule_inputs(vehicle, options, speeds_mps);
  // The lead wheel's curvature rate on the reference path, per lead wheelbase (it depends on the
  // chain, not on the speed).
  const int nodes = options.order == 2 ? kLeadWheelbaseNodes : 1;
  std::vector<double> rate_demands(static_cast<std::size_t>(nodes), -1.0);
  if (options.reference_path && std::isfinite(options.path_curvature_rate_bound)) {
    for (int i = 1; i <= nodes; ++i) {
      ScheduleEntry probe;
      probe.lead_wheelbase_m = options.order == 2 ? lead_wheelbase_node(vehicle, i, nodes) : 0.0;
      probe.lead_curvature_bound = 1e-3;
      probe.k_rob = options.k_rob_floor;
      const ControllerParameters p = schedule_entry_parameters(options, vehicle.wheelbase_m, probe);
      rate_demands[static_cast<std::size_t>(i - 1)] =
          std::max(options.path_curvature_rate_bound,
                   lead_curvature_rate_demand(*options.reference_path, p.chain.wheelbases_m.data(),
                                              p.chain.order));
    }
  }
  std::vector<ScheduleEntry> entries;
  entries.reserve(speeds_mps.size());
  for (std::size_t k = 0; k < speeds_mps.size(); ++k) {
    const double v = speeds_mps[k];
    const TuningOptions& here = at_speed[k];
    ScheduleEntry best;
    for (int i = 1; i <= nodes; ++i) {
      const double lead = lead_wheelbase_node(vehicle, i, nodes);
      const ScheduleEntry e =
          solve_node({vehicle, here, v, lead, rate_demands[static_cast<std::size_t>(i - 1)]});
      // O3: the largest switching authority; O4: ties keep the shorter lead wheelbase.
      if (e.lead_curvature_bound > best.lead_curvature_bound * (1.0 + 1e-9)) best = e;
    }
    const double switching = best.lead_curvature_bound - best.feedforward_curvature_bound;
    if (best.lead_curvature_bound <= 0.0 || switching < here.min_lead_curvature_bound ||
        best.k_rob >= here.k_rob_ceiling) {
      throw_infeasible({vehicle, here, v, best.lead_wheelbase_m}, best);
    }
    entries.push_back(best);
    if (speed_solved) speed_solved();
  }
  // Certify the online blends as the box route does: entries k and k+1 mixed must hold at v_k;
  // otherwise shrink entry k's switching authority (it stays valid at v_k).
  for (std::size_t k = entries.size(); k-- > 0;) {
    const std::size_t next = std::min(k + 1, entries.size() - 1);
    const SpeedProblem problem{vehicle, at_speed[k], entries[k].speed_mps,
                               entries[k].lead_wheelbase_m};
    for (int attempt = 0; attempt < 200; ++attempt) {
      bool ok = true;
      for (const double t : {0.25, 0.5, 0.75}) {
        ScheduleEntry mix = blend_entries(entries[k], entries[next], t);
        ok = ok && problem.certify(mix);
      }
      if (ok) break;
      ScheduleEntry& e = entries[k];
      const double switching = (e.lead_curvature_bound - e.feedforward_curvature_bound) * 0.99;
      const VelocityRegion region = e.region;
      e = problem.entry(e.feedforward_curvature_bound, e.feedforward_curvature_rate, switching);
      e.region = region;
      problem.certify(e);
    }
  }
  return GainSchedule(vehicle, options, std::move(entries));
}

}  // namespace

GainSchedule compute_feedforward_schedule(const VehicleLimits& vehicle,
                                          const TuningOptions& options,
                                          const std::vector<double>& speeds_mps,
                                          const SpeedSolved& speed_solved) {
  return feedforward_schedule(vehicle, options,
                              std::vector<TuningOptions>(speeds_mps.size(), options), speeds_mps,
                              speed_solved);
}

GainSchedule compute_domain_schedule(const VehicleLimits& vehicle, const TuningOptions& options,
                                     const DrivingDomain& domain,
                                     const std::vector<double>& speeds_mps) {
  domain.validate();
  if (options.reference_path) {
    throw std::invalid_argument(
        "compute_domain_schedule: options.reference_path is set; the domain replaces the path "
        "(use compute_feedforward_schedule for one path)");
  }
  std::vector<TuningOptions> at_speed(speeds_mps.size(), options);
  for (std::size_t k = 0; k < speeds_mps.size(); ++k) {
    at_speed[k].path_curvature_bound = domain.curvature_at(speeds_mps[k]);
    at_speed[k].path_curvature_rate_bound = domain.curvature_rate_at(speeds_mps[k]);
  }
  return feedforward_schedule(vehicle, options, at_speed, speeds_mps, {});
}

ControllerParameters parameters_for_vehicle(const VehicleLimits& vehicle, double speed_mps,
                                            const TuningOptions& options) {
  TuningOptions feedforward = options;
  feedforward.certificate = Certificate::feedforward;
  const GainSchedule schedule = compute_feedforward_schedule(vehicle, feedforward, {speed_mps});
  return schedule_entry_parameters(feedforward, vehicle.wheelbase_m, schedule.entries().front());
}

}  // namespace smoothsteer
