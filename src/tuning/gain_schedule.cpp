#include "smoothsteer/tuning/gain_schedule.hpp"

#include "smoothsteer/controller/steering_governor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "smoothsteer/controller/trailer_chain.hpp"
#include "smoothsteer/tuning/invariant_bounds.hpp"
#include "smoothsteer/tuning/worst_case.hpp"

namespace smoothsteer {
namespace {

constexpr double kExactTolerance = 1e-9;  // relative slack of the exact certification
constexpr int kBisections = 60;

struct Problem {
  const VehicleLimits& vehicle;
  const TuningOptions& options;
  double speed = 0.0;
  //! Worst-case time-domain rate and acceleration for dimensionless R, A (O1, O2).
  double rate(double r_hat) const { return speed * r_hat / vehicle.wheelbase_m; }
  double acceleration(double r_hat, double a_hat) const {
    const double l = vehicle.wheelbase_m;
    return speed * speed * a_hat / (l * l) + options.max_longitudinal_acceleration_mps2 * r_hat / l;
  }
  bool rate_ok(const MapValue& m) const { return rate(m.rate) <= vehicle.max_steering_rate_radps; }
  bool acceleration_ok(const MapValue& m) const {
    return acceleration(m.rate, m.acceleration) <= vehicle.max_steering_acceleration_radps2;
  }
};

ControllerParameters parameters_for(const TuningOptions& options, double vehicle_wheelbase,
                                    double lead_wheelbase, double kbar, double k_rob) noexcept {
  if (options.order == 1) {
    ControllerParameters p = options.base;
    p.chain.order = 1;
    p.chain.vehicle_wheelbase_m = vehicle_wheelbase;
    p.chain.wheelbases_m[0] = vehicle_wheelbase;
    p.chain.lead_curvature_bound = kbar;
    p.law.k_rob = k_rob;
    return p;
  }
  return second_order_parameters(options.base, vehicle_wheelbase, lead_wheelbase, kbar, k_rob);
}

}  // namespace

ScheduleEntry blend_entries(const ScheduleEntry& a, const ScheduleEntry& b, double t) noexcept {
  auto blend = [t](double x, double y) { return x + t * (y - x); };
  ScheduleEntry e = a;
  e.lead_wheelbase_m = blend(a.lead_wheelbase_m, b.lead_wheelbase_m);
  e.lead_curvature_bound = blend(a.lead_curvature_bound, b.lead_curvature_bound);
  e.k_rob = blend(a.k_rob, b.k_rob);
  e.feedforward_curvature_bound =
      blend(a.feedforward_curvature_bound, b.feedforward_curvature_bound);
  e.feedforward_curvature_rate = blend(a.feedforward_curvature_rate, b.feedforward_curvature_rate);
  return e;
}

namespace {

//! Exact worst case of the time-domain derivatives for parameters p at speed v.
struct Exact {
  double angle, rate, acceleration;
};
Exact exact_at(const Problem& problem, const ControllerParameters& p) {
  const SteeringDerivatives worst = worst_case_steering_derivatives(p);
  const double v = problem.speed;
  const double a = problem.options.max_longitudinal_acceleration_mps2;
  return {compute_chain_bounds(p).steering_angle_rad, v * worst.rate_per_meter,
          v * v * worst.acceleration_per_meter2 + a * worst.rate_per_meter};
}

bool exact_ok(const Problem& problem, const Exact& e) {
  const VehicleLimits& l = problem.vehicle;
  return e.angle <= l.max_steering_angle_rad * (1.0 + kExactTolerance) &&
         e.rate <= l.max_steering_rate_radps * (1.0 + kExactTolerance) &&
         (std::isinf(l.max_steering_acceleration_radps2) ||
          e.acceleration <= l.max_steering_acceleration_radps2 * (1.0 + kExactTolerance));
}

ScheduleEntry make_entry(const Problem& problem, VelocityRegion region, double lead_wheelbase,
                         double kbar) {
  const TuningOptions& o = problem.options;
  ScheduleEntry entry;
  entry.speed_mps = problem.speed;
  entry.region = region;
  entry.lead_wheelbase_m = o.order == 2 ? lead_wheelbase : 0.0;
  entry.lead_curvature_bound = kbar;
  entry.k_rob = minimum_k_rob(o.matched_disturbance_curvature, o.path_curvature_bound, kbar,
                              o.k_rob_floor, o.k_rob_ceiling);
  const ControllerParameters p =
      parameters_for(o, problem.vehicle.wheelbase_m, entry.lead_wheelbase_m, kbar, entry.k_rob);
  entry.fictive_wheelbase_m = p.chain.wheelbases_m[0];
  const Exact e = exact_at(problem, p);
  entry.max_steering_angle_rad = e.angle;
  entry.max_steering_rate_radps = e.rate;
  entry.max_steering_acceleration_radps2 = e.acceleration;
  return entry;
}

std::string format_speed(double v) {
  std::ostringstream text;
  text << "v = " << v << " m/s";
  return text.str();
}

//! Largest q in [0, cap] for which `ok` holds at r node `index` (R and A grow with q).
template <class Ok>
double largest_q(const StaticMap& map, int index, double cap, Ok&& ok) {
  if (ok(map.lookup_node(index, cap))) return cap;
  double low = 0.0, high = cap;
  for (int iteration = 0; iteration < kBisections; ++iteration) {
    const double mid = 0.5 * (low + high);
    (ok(map.lookup_node(index, mid)) ? low : high) = mid;
  }
  return low;
}

[[noreturn]] void throw_infeasible(const Problem& problem, const StaticMap* map, double required_q,
                                   double best_kbar) {
  const VehicleLimits& l = problem.vehicle;
  std::string binding = "steering rate";
  if (map != nullptr) {
    bool any_rate = false, any_acceleration = false;
    for (int i = 0; i < map->ratio_count(); ++i) {
      const MapValue m = map->lookup_node(i, required_q);
      any_rate = any_rate || problem.rate_ok(m);
      any_acceleration = any_acceleration || problem.acceleration_ok(m);
    }
    binding = !any_acceleration
                  ? (any_rate ? "steering acceleration" : "steering rate and acceleration")
              : !any_rate ? "steering rate"
                          : "steering rate and acceleration";
  }
  std::ostringstream text;
  text.precision(6);
  const double required = required_q / l.wheelbase_m;
  text << "infeasible limits at " << format_speed(problem.speed) << ": the " << binding
       << " limit (";
  if (binding.find("rate") != std::string::npos) text << l.max_steering_rate_radps << " rad/s";
  if (binding == "steering rate and acceleration") text << ", ";
  if (binding.find("acceleration") != std::string::npos) {
    text << l.max_steering_acceleration_radps2 << " rad/s^2";
  }
  text << ") binds: ";
  if (map != nullptr)
    text << "no lead wheelbase lambda_l in (0, " << l.wheelbase_m << ") m meets it ";
  text << "with kbar_l >= " << required << " 1/m (lead radius <= " << 1.0 / required
       << " m, from min_lead_curvature_bound and k_rob <= " << problem.options.k_rob_ceiling
       << "); the largest admissible kbar_l at this speed is " << best_kbar
       << " 1/m. Relax that limit, lower the top speed or min_lead_curvature_bound.";
  throw InfeasibleLimits(text.str(), problem.speed, binding);
}

ScheduleEntry solve_first_order(const Problem& problem, double required_q) {
  const VehicleLimits& l = problem.vehicle;
  // n = 1, lambda = lambda_veh: worst rate 2 kbar_0 (tests/tuning), angle atan(lambda kbar_0).
  const double angle_kbar0 = std::tan(l.max_steering_angle_rad) / l.wheelbase_m;
  const double rate_kbar0 = l.max_steering_rate_radps / (2.0 * problem.speed);
  const double kbar0 = std::min(angle_kbar0, rate_kbar0);
  double kbar = kbar0 / std::sqrt(1.0 + kbar0 * kbar0 * l.wheelbase_m * l.wheelbase_m);
  if (kbar * l.wheelbase_m < required_q) throw_infeasible(problem, nullptr, required_q, kbar);
  const VelocityRegion region =
      angle_kbar0 <= rate_kbar0 ? VelocityRegion::region1 : VelocityRegion::rate_only;
  ScheduleEntry entry = make_entry(problem, region, 0.0, kbar);
  for (int shrink = 0; shrink < 100 && !exact_ok(problem, {entry.max_steering_angle_rad,
                                                           entry.max_steering_rate_radps, 0.0});
       ++shrink) {
    kbar *= 1.0 - 1e-9 * (1 << std::min(shrink, 20));
    entry = make_entry(problem, region, 0.0, kbar);
  }
  return entry;
}

ScheduleEntry solve_second_order(const Problem& problem, const StaticMap& map, double required_q) {
  const VehicleLimits& l = problem.vehicle;
  const double cap = std::sin(l.max_steering_angle_rad);  // eq. (kappalmax), corrected
  // Per r node: the largest q that O1 allows and the largest that O2 allows; q_i = min of both.
  const int count = map.ratio_count();
  std::vector<double> rate_q(static_cast<std::size_t>(count)), acceleration_q(rate_q.size());
  double best_q = -1.0;
  int best_index = 0;
  for (int i = 0; i < count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    rate_q[k] = largest_q(map, i, cap, [&](const MapValue& m) { return problem.rate_ok(m); });
    acceleration_q[k] =
        largest_q(map, i, cap, [&](const MapValue& m) { return problem.acceleration_ok(m); });
    const double q = std::min(rate_q[k], acceleration_q[k]);
    if (q > best_q * (1.0 + 1e-12)) best_q = q, best_index = i;  // ties keep the smaller r (O4)
  }
  if (best_q < required_q) throw_infeasible(problem, &map, required_q, best_q / l.wheelbase_m);
  // Region labels (Sec. III): which limit caps q at the optimum, and whether the optimum sits on
  // the crossing of the O1 and O2 curves (region 3) or at the top of the O2 curve (region 4).
  const auto b = static_cast<std::size_t>(best_index);
  VelocityRegion region = VelocityRegion::rate_only;
  if (best_q >= cap * (1.0 - 1e-12)) {
    region = best_index == 0 ? VelocityRegion::region1 : VelocityRegion::region2;
  } else if (rate_q[b] <= acceleration_q[b]) {
    region = best_index == 0 ? VelocityRegion::rate_only : VelocityRegion::region3;
  } else {
    const bool crossing = b + 1 < rate_q.size() && rate_q[b + 1] <= acceleration_q[b];
    region = crossing ? VelocityRegion::region3 : VelocityRegion::region4;
  }
  const double lead = map.ratio_at(best_index) * l.wheelbase_m;
  ScheduleEntry entry = make_entry(problem, region, lead, best_q / l.wheelbase_m);
  // Certify with the exact worst case; the table is conservative, so this rarely shrinks.
  double q = best_q;
  for (int shrink = 0; shrink < 200 && !exact_ok(problem, {entry.max_steering_angle_rad,
                                                           entry.max_steering_rate_radps,
                                                           entry.max_steering_acceleration_radps2});
       ++shrink) {
    q *= 1.0 - 1e-9 * (1 << std::min(shrink, 24));
    if (q < required_q) throw_infeasible(problem, &map, required_q, q / l.wheelbase_m);
    entry = make_entry(problem, region, lead, q / l.wheelbase_m);
  }
  return entry;
}

}  // namespace

const char* to_string(VelocityRegion region) noexcept {
  switch (region) {
    case VelocityRegion::region1:
      return "1 (angle)";
    case VelocityRegion::region2:
      return "2 (acceleration, lambda_l grows)";
    case VelocityRegion::region3:
      return "3 (rate + acceleration, kbar_l shrinks)";
    case VelocityRegion::region4:
      return "4 (acceleration at min delta'')";
    case VelocityRegion::rate_only:
      return "rate only";
  }
  return "?";
}

std::optional<Violation> TuningOptions::first_violation() const noexcept {
  RuleChecker check("TuningOptions");
  check.require(order >= 1 && order <= 2, "order", order,
                "must be 1 or 2 (n >= 3: see docs/tuning.md, 'Beyond n = 2')");
  check.require_non_negative(
      {{"max_longitudinal_acceleration_mps2", max_longitudinal_acceleration_mps2}});
  check.require_positive({{"min_lead_curvature_bound", min_lead_curvature_bound}});
  check.require_non_negative({{"matched_disturbance_curvature", matched_disturbance_curvature},
                              {"path_curvature_bound", path_curvature_bound}});
  check.require(path_curvature_rate_bound >= 0.0, "path_curvature_rate_bound",
                path_curvature_rate_bound, "must be >= 0 (+inf: unknown)");
  check.require(std::isfinite(feedforward_rate_margin) && feedforward_rate_margin >= 1.0,
                "feedforward_rate_margin", feedforward_rate_margin, "must be finite and >= 1");
  check.require(feedforward_headroom >= 1.0 && feedforward_headroom <= 3.0, "feedforward_headroom",
                feedforward_headroom, "must be in [1, 3]");
  check.require(feedforward_rate_share > 0.0 && feedforward_rate_share < 1.0,
                "feedforward_rate_share", feedforward_rate_share, "must be in (0, 1)");
  check.require_positive({{"feedforward_ramp_length_m", feedforward_ramp_length_m}});
  check.require(switching_floor_share > 0.0 && switching_floor_share < 1.0, "switching_floor_share",
                switching_floor_share, "must be in (0, 1)");
  check.require(k_rob_ceiling > 0.0 && k_rob_ceiling < 1.0, "k_rob_ceiling", k_rob_ceiling,
                "must be in (0, 1)");
  check.require(k_rob_floor >= 0.0 && k_rob_floor < k_rob_ceiling, "k_rob_floor", k_rob_floor,
                "must be in [0, k_rob_ceiling)");
  return check.first();
}

GainSchedule::GainSchedule(VehicleLimits vehicle, TuningOptions options,
                           std::vector<ScheduleEntry> entries)
    : vehicle_(vehicle), options_(options), entries_(std::move(entries)) {}

ControllerParameters GainSchedule::parameters_at(double speed_mps) const noexcept {
  if (entries_.empty()) return options_.base;
  const double speed = std::isfinite(speed_mps) ? std::abs(speed_mps) : 0.0;
  const auto it =
      std::lower_bound(entries_.begin(), entries_.end(), speed,
                       [](const ScheduleEntry& e, double v) { return e.speed_mps < v; });
  const std::size_t last = entries_.size() - 1;
  std::size_t k = static_cast<std::size_t>(it - entries_.begin());
  double t = 0.0;
  if (k > last) {
    k = last;
  } else {
    const double lower = k == 0 ? 0.0 : entries_[k - 1].speed_mps;
    t = std::clamp((speed - lower) / (entries_[k].speed_mps - lower), 0.0, 1.0);
  }
  const ScheduleEntry& a = entries_[k];
  const ScheduleEntry& b = entries_[std::min(k + 1, last)];
  const ControllerParameters certified =
      schedule_entry_parameters(options_, vehicle_.wheelbase_m, blend_entries(a, b, t));
  return governed_parameters(certified, speed);  // unchanged unless base.governor.enabled
}

std::vector<double> speed_grid(double first_mps, double last_mps, double step_mps) {
  if (!(first_mps > 0.0) || !std::isfinite(first_mps) || !(last_mps >= first_mps) ||
      !std::isfinite(last_mps) || !(step_mps > 0.0) || !std::isfinite(step_mps)) {
    std::ostringstream text;
    text << "speed grid " << first_mps << ":" << last_mps << ":" << step_mps
         << " must satisfy 0 < first <= last and step > 0 (all finite)";
    throw std::invalid_argument(text.str());
  }
  // Counted in double first: 1:1e300:1e-300 gives 1e600 = inf, which no integer holds.
  const double steps = std::floor((last_mps - first_mps) / step_mps + 1e-9);
  if (!(steps < 100000.0)) throw std::invalid_argument("speed grid has more than 100000 speeds");
  const long count = static_cast<long>(steps) + 1;
  std::vector<double> speeds;
  for (long k = 0; k < count; ++k) speeds.push_back(first_mps + static_cast<double>(k) * step_mps);
  return speeds;
}

void check_speed_grid(const std::vector<double>& speeds_mps) {
  if (speeds_mps.empty()) throw std::invalid_argument("compute_gain_schedule: no speeds given");
  for (std::size_t k = 0; k < speeds_mps.size(); ++k) {
    const double v = speeds_mps[k];
    if (!std::isfinite(v) || v <= 0.0 || (k > 0 && v <= speeds_mps[k - 1])) {
      std::ostringstream text;
      text << "compute_gain_schedule: speeds_mps[" << k << "] = " << v
           << " must be finite, > 0 and strictly increasing";
      throw std::invalid_argument(text.str());
    }
  }
}

void check_schedule_inputs(const VehicleLimits& vehicle, const TuningOptions& options,
                           const std::vector<double>& speeds_mps) {
  vehicle.validate();
  options.validate();
  check_speed_grid(speeds_mps);
  if (options.order == 1 && std::isfinite(vehicle.max_steering_acceleration_radps2)) {
    throw std::invalid_argument(
        "order 1 cannot bound the steering acceleration (kappa_f switches, eq. ext1b): set "
        "max_steering_acceleration_radps2 to inf or use order 2");
  }
}

ControllerParameters schedule_entry_parameters(const TuningOptions& options,
                                               double vehicle_wheelbase_m,
                                               const ScheduleEntry& entry) noexcept {
  ControllerParameters p = parameters_for(options, vehicle_wheelbase_m, entry.lead_wheelbase_m,
                                          entry.lead_curvature_bound, entry.k_rob);
  p.feedforward.share = entry.feedforward_curvature_bound / entry.lead_curvature_bound;
  p.feedforward.curvature_rate = entry.feedforward_curvature_rate;
  return p;
}

GainSchedule compute_gain_schedule(const VehicleLimits& vehicle, const TuningOptions& options,
                                   const std::vector<double>& speeds_mps, const StaticMap& map,
                                   const SpeedSolved& speed_solved) {
  if (options.certificate == Certificate::feedforward) {
    return compute_feedforward_schedule(vehicle, options, speeds_mps, speed_solved);
  }
  check_schedule_inputs(vehicle, options, speeds_mps);
  if (options.order == 2 && vehicle.max_steering_angle_rad > map.options().max_steering_angle_rad) {
    std::ostringstream text;
    text << "VehicleLimits: max_steering_angle_rad = " << vehicle.max_steering_angle_rad
         << " exceeds the static map's max_steering_angle_rad = "
         << map.options().max_steering_angle_rad << "; build the map with a larger angle";
    throw std::invalid_argument(text.str());
  }
  // kbar_l must reach min_lead_curvature_bound and keep k_rob below its ceiling (item 2).
  const double disturbance = options.matched_disturbance_curvature + options.path_curvature_bound;
  const double required_kbar = std::max(options.min_lead_curvature_bound,
                                        disturbance / options.k_rob_ceiling * (1.0 + 1e-9));
  const double required_q = required_kbar * vehicle.wheelbase_m;
  if (std::sin(vehicle.max_steering_angle_rad) < required_q) {
    Problem problem{vehicle, options, speeds_mps.front()};
    std::ostringstream text;
    text << "infeasible limits at " << format_speed(problem.speed) << ": the steering angle limit ("
         << vehicle.max_steering_angle_rad << " rad) binds: it allows kbar_l <= "
         << std::sin(vehicle.max_steering_angle_rad) / vehicle.wheelbase_m
         << " 1/m (eq. kappalmax) < the required " << required_kbar << " 1/m";
    throw InfeasibleLimits(text.str(), problem.speed, "steering angle");
  }
  std::vector<ScheduleEntry> entries;
  entries.reserve(speeds_mps.size());
  for (const double v : speeds_mps) {
    const Problem problem{vehicle, options, v};
    entries.push_back(options.order == 1 ? solve_first_order(problem, required_q)
                                         : solve_second_order(problem, map, required_q));
    if (speed_solved) speed_solved();
  }
  // Certify the online blends: on [v_{k-1}, v_k] parameters_at() mixes entries k and k+1, which
  // must hold at v_k. If a mid-blend fails (the feasible set is not convex in general), shrink
  // kbar_l of entry k: it stays valid for v_k (R, A grow with kbar_l). Backwards, because
  // entry k also enters the blend of the interval below.
  for (std::size_t k = entries.size(); k-- > 0;) {
    const std::size_t next = std::min(k + 1, entries.size() - 1);
    const Problem problem{vehicle, options, entries[k].speed_mps};
    for (int attempt = 0; attempt < 60; ++attempt) {
      bool ok = true;
      for (const double t : {0.25, 0.5, 0.75}) {
        const ControllerParameters p = schedule_entry_parameters(
            options, vehicle.wheelbase_m, blend_entries(entries[k], entries[next], t));
        ok = ok && exact_ok(problem, exact_at(problem, p));
      }
      if (ok) break;
      ScheduleEntry& e = entries[k];
      e = make_entry(problem, e.region, e.lead_wheelbase_m, e.lead_curvature_bound * 0.995);
    }
  }
  return GainSchedule(vehicle, options, std::move(entries));
}

}  // namespace smoothsteer
