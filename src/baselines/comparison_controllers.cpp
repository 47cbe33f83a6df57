#include "smoothsteer/baselines/comparison_controllers.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "baseline_common.hpp"
#include "smoothsteer/baselines/hosm_controller.hpp"
#include "smoothsteer/controller/lead_wheel_controller.hpp"

namespace smoothsteer {

std::optional<Violation> ComparisonSetup::first_violation() const noexcept {
  RuleChecker check("ComparisonSetup");
  // Upper bounds: beyond them the bisection of proposed_parameters and the baselines' gains
  // overflow (wheelbase_m = 1e308 must be rejected, not turned into inf).
  check.require(positive_finite(wheelbase_m) && wheelbase_m <= max_wheelbase_m, "wheelbase_m",
                wheelbase_m, "must be in (0, 1000]");
  check.require(positive_finite(nominal_speed_mps) &&
                    nominal_speed_mps <= ControllerInputRange::max_abs_speed_mps,
                "nominal_speed_mps", nominal_speed_mps, "must be in (0, 1000]");
  check.include(limits.first_violation());
  check.require(std::isfinite(k_rob) && k_rob >= 0.0 && k_rob < 1.0, "k_rob", k_rob,
                "must be in [0, 1)");
  check.require(positive_finite(lead_wheelbase_m) && lead_wheelbase_m < wheelbase_m,
                "lead_wheelbase_m", lead_wheelbase_m,
                "must be in (0, wheelbase_m) (eq. cornering_constr)");
  return check.first();
}

std::string ComparisonSetup::validation_error() const {
  if (!path) return "ComparisonSetup: path is null; a path is required";
  return describe(first_violation());
}

void ComparisonSetup::validate() const {
  if (const std::string error = validation_error(); !error.empty()) {
    throw std::invalid_argument(error);
  }
}

const std::vector<std::string>& comparison_controller_names() {
  static const std::vector<std::string> names{
      "dubins_smc", "proposed_c0",  "proposed_c1", "hosm", "newton_raphson",
      "stanley",    "pure_pursuit", "lqr",         "mpc",  "mpc_constrained"};
  return names;
}

double hosm_heading_bound_for(double requested_rad, double wheelbase_m, double angle_bound_rad,
                              double rate_bound_per_m) noexcept {
  const double curvature = std::tan(angle_bound_rad) / wheelbase_m;
  const double largest = std::atan(rate_bound_per_m / (2.0 * wheelbase_m * curvature * curvature));
  return std::min(requested_rad, largest);
}

namespace {

// Largest kbar_n whose chain keeps |delta_veh| <= delta-bar and |d delta_veh/ds| <= delta-bar'.
// Both bounds grow monotonically with kbar_n, so bisection on compute_chain_bounds finds it.
ControllerParameters proposed_parameters(const ComparisonSetup& setup, int order) {
  ControllerParameters parameters =
      order == 1 ? ControllerParameters::paper_c0(setup.wheelbase_m, 0.1, setup.k_rob)
                 : ControllerParameters::paper_c1(setup.wheelbase_m, setup.lead_wheelbase_m, 0.1,
                                                  setup.k_rob);
  const double rate_per_meter = setup.limits.rate_radps / setup.nominal_speed_mps;
  double low = 0.0;
  double high = 1.0 / parameters.chain.wheelbases_m[static_cast<std::size_t>(order - 1)];
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double middle = 0.5 * (low + high);
    parameters.chain.lead_curvature_bound = middle;
    bool fits = parameters.validation_error().empty();
    if (fits) {
      const ChainBounds bounds = compute_chain_bounds(parameters);
      fits = bounds.steering_angle_rad <= setup.limits.angle_rad &&
             bounds.steering_rate_per_meter <= rate_per_meter;
    }
    (fits ? low : high) = middle;
  }
  parameters.chain.lead_curvature_bound = low;
  parameters.validate();
  return parameters;
}

std::unique_ptr<SteeringController> make_inner(std::string_view name,
                                               const ComparisonSetup& setup) {
  const double lambda = setup.wheelbase_m;
  if (name == "dubins_smc") {
    // Built field by field: paper_c0 would validate an n = 1 chain, whose invariant set needs
    // kbar lambda < 1, which tan(delta-bar) >= 1 (delta-bar >= pi/4) breaks.
    ControllerParameters parameters;
    parameters.chain.order = 0;
    parameters.chain.vehicle_wheelbase_m = lambda;
    parameters.chain.lead_curvature_bound = std::tan(setup.limits.angle_rad) / lambda;
    parameters.law.k_rob = setup.k_rob;
    return std::make_unique<LeadWheelController>(parameters, setup.path);
  }
  if (name == "proposed_c0") {
    return std::make_unique<LeadWheelController>(proposed_parameters(setup, 1), setup.path);
  }
  if (name == "proposed_c1") {
    return std::make_unique<LeadWheelController>(proposed_parameters(setup, 2), setup.path);
  }
  if (name == "hosm") {
    HosmParameters parameters;
    parameters.wheelbase_m = lambda;
    parameters.steering_angle_bound_rad = setup.limits.angle_rad;
    parameters.steering_rate_bound_per_m = setup.limits.rate_radps / setup.nominal_speed_mps;
    parameters.heading_bound_rad =
        hosm_heading_bound_for(setup.hosm_heading_bound_rad, lambda, setup.limits.angle_rad,
                               parameters.steering_rate_bound_per_m);
    return std::make_unique<HosmController>(parameters, setup.path);
  }
  if (name == "newton_raphson") {
    NewtonRaphsonParameters parameters = setup.newton_raphson;
    parameters.wheelbase_m = lambda;
    parameters.limits = setup.limits;
    return std::make_unique<NewtonRaphsonController>(parameters, setup.path);
  }
  if (name == "stanley") {
    StanleyParameters parameters = setup.stanley;
    parameters.wheelbase_m = lambda;
    return std::make_unique<StanleyController>(parameters, setup.path);
  }
  if (name == "pure_pursuit") {
    PurePursuitParameters parameters = setup.pure_pursuit;
    parameters.wheelbase_m = lambda;
    return std::make_unique<PurePursuitController>(parameters, setup.path);
  }
  if (name == "lqr") {
    LqrParameters parameters = setup.lqr;
    parameters.wheelbase_m = lambda;
    return std::make_unique<LqrController>(parameters, setup.path);
  }
  if (name == "mpc" || name == "mpc_constrained") {
    MpcParameters parameters = setup.mpc;
    parameters.wheelbase_m = lambda;
    parameters.limits = setup.limits;
    parameters.solver = name == "mpc" ? MpcSolver::unconstrained : MpcSolver::constrained;
    return std::make_unique<MpcController>(parameters, setup.path);
  }
  std::string known;
  for (const std::string& candidate : comparison_controller_names()) {
    known += (known.empty() ? "" : ", ") + candidate;
  }
  throw std::invalid_argument("make_comparison_controller: name = '" + std::string(name) +
                              "' is not a comparison controller; known: " + known);
}

}  // namespace

std::unique_ptr<SaturatedController> make_comparison_controller(std::string_view name,
                                                                const ComparisonSetup& setup) {
  setup.validate();
  return std::make_unique<SaturatedController>(make_inner(name, setup), setup.limits,
                                               std::string(name));
}

}  // namespace smoothsteer
