// Cost of LeadWheelController::update for n = 0, 1, 2, 4 on a straight line and on a curved
// 10 000-waypoint spline, while tracking (warm-started projection). Poses come from a recorded
// closed loop so that only update() is timed. Figures: docs/benchmarks.md.

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

#include "smoothsteer/smoothsteer.hpp"
#include "support/recorded_inputs.hpp"

namespace {

using namespace smoothsteer;

std::shared_ptr<const Path> curved_path() {
  static const std::shared_ptr<const Path> path = [] {
    std::vector<Vec2> waypoints;
    waypoints.reserve(10000);
    for (int k = 0; k < 10000; ++k) {
      const double x = 0.5 * k;
      waypoints.push_back({x, 15.0 * std::sin(x / 40.0) + 4.0 * std::sin(x / 13.0)});
    }
    return std::make_shared<const Path>(Path::from_waypoints(waypoints));
  }();
  return path;
}

//! circle_sections' path (scenarios/circle_sections.yaml): lines and arcs of 30-50 m, with
//! five curvature jumps.
std::shared_ptr<const Path> circle_sections_path() {
  static const auto path = std::make_shared<const Path>(PathBuilder({0.0, 0.0}, 0.0)
                                                            .line(15.0)
                                                            .arc(30.0, pi / 2.0)
                                                            .arc(40.0, -pi)
                                                            .arc(50.0, pi)
                                                            .arc(30.0, -pi / 2.0)
                                                            .line(30.0)
                                                            .build());
  return path;
}

std::shared_ptr<const Path> straight_path() {
  static const auto path =
      std::make_shared<const Path>(Path::straight_line({0.0, 0.0}, 0.0, 5000.0));
  return path;
}

//! How the lead wheel's target is computed (docs/feedforward.md).
enum class Law {
  defaults,  //!< ControllerParameters{}: feedforward without rate limit, rear-axle target
  preview,   //!< rate-limited feedforward with preview, as the certified schedules use it
  exact,     //!< the same with the exact rear-axle target and the single-track inversion
  planned,   //!< the same with the planned curvature jumps (jump_plan.hpp)
  governed,  //!< the exact target with the steering governor (docs/governor.md), the car's limits
  shipped,   //!< as the shipped scenarios: the governor with planned jumps and its derived length
  paper,     //!< the paper's law: no feedforward, the lead wheel on the path
};

ControllerParameters parameters_of_order(int order, Law law = Law::defaults) {
  ControllerParameters parameters;
  parameters.chain.order = order;
  parameters.chain.lead_curvature_bound = 0.1;
  const bool governed = law == Law::governed || law == Law::shipped;
  if (law == Law::preview || law == Law::exact || law == Law::planned || governed) {
    parameters.feedforward.curvature_rate = 0.005;
  }
  if (law == Law::exact || law == Law::planned || governed) {
    parameters.feedforward.cornering_target = CorneringTarget::rear_axle_exact;
    parameters.single_track = {
        .enabled = true, .rear_slip_gradient_s2pm = 0.00465, .front_slip_gradient_s2pm = 0.00465};
  }
  if (law == Law::planned || law == Law::shipped)
    parameters.feedforward.curvature_preview = CurvaturePreview::planned_jumps;
  if (governed && order >= 1 && order <= 2) {
    parameters.governor.enabled = true;
    parameters.governor.max_steering_rate_radps = 0.4;
    parameters.governor.max_steering_acceleration_radps2 = 8.0;
    // The shipped scenarios derive the far law's length per sub-step (eq. governed_law_length).
    if (law != Law::shipped) {
      parameters.governor.fixed_law_length = true;
      parameters.governor.law_length_m = 6.0;
    }
    parameters.governor.near_law_switching_bound = 0.005;
  }
  if (law == Law::paper) {
    parameters.feedforward.share = 0.0;
    parameters.law.boundary_layer = 0.0;
    parameters.feedforward.cornering_target = CorneringTarget::lead_wheel;
  }
  return parameters;
}

void update_cost(benchmark::State& state, const std::shared_ptr<const Path>& path,
                 Law law = Law::defaults) {
  const int order = static_cast<int>(state.range(0));
  const std::vector<ControllerInput> inputs =
      bench::recorded_inputs(path, parameters_of_order(order, law));
  LeadWheelController controller(parameters_of_order(order, law), path);
  ControllerOutput output;
  std::size_t index = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(controller.update(inputs[index], output));
    benchmark::DoNotOptimize(output.steering_angle_rad);
    if (++index == inputs.size()) index = 0;
  }
  state.SetLabel("n=" + std::to_string(order));
}

void BM_UpdateStraightLine(benchmark::State& state) {
  update_cost(state, straight_path());
}
void BM_UpdateCurvedPath10k(benchmark::State& state) {
  update_cost(state, curved_path());
}
void BM_UpdateCurvedPath10kPreview(benchmark::State& state) {
  update_cost(state, curved_path(), Law::preview);
}
void BM_UpdateCurvedPath10kExactTarget(benchmark::State& state) {
  update_cost(state, curved_path(), Law::exact);
}
void BM_UpdateCurvedPath10kPlannedJumps(benchmark::State& state) {
  update_cost(state, curved_path(), Law::planned);
}
void BM_UpdateCurvedPath10kGoverned(benchmark::State& state) {
  update_cost(state, curved_path(), Law::governed);
}
void BM_UpdateCurvedPath10kShipped(benchmark::State& state) {
  update_cost(state, curved_path(), Law::shipped);
}
void BM_UpdateCircleSectionsShipped(benchmark::State& state) {
  update_cost(state, circle_sections_path(), Law::shipped);
}
void BM_UpdateCircleSectionsExactTarget(benchmark::State& state) {
  update_cost(state, circle_sections_path(), Law::exact);
}
void BM_UpdateCircleSectionsPlannedJumps(benchmark::State& state) {
  update_cost(state, circle_sections_path(), Law::planned);
}
void BM_UpdateCurvedPath10kPaperLaw(benchmark::State& state) {
  update_cost(state, curved_path(), Law::paper);
}

//! Worst case: 30 m from the 10 000-segment path every projection is a global search.
void BM_UpdateFarFromCurvedPath10k(benchmark::State& state) {
  const int order = static_cast<int>(state.range(0));
  LeadWheelController controller(parameters_of_order(order), curved_path());
  ControllerOutput output;
  double x = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(controller.update({{x, 60.0}, 0.0, 10.0, 0.0, 0.02}, output));
    x = x < 4000.0 ? x + 0.2 : 0.0;
  }
  state.SetLabel("n=" + std::to_string(order));
}

BENCHMARK(BM_UpdateStraightLine)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Arg(4)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);
BENCHMARK(BM_UpdateCurvedPath10k)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Arg(4)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);
BENCHMARK(BM_UpdateCurvedPath10kPreview)->Arg(1)->Arg(2);
BENCHMARK(BM_UpdateCurvedPath10kExactTarget)->Arg(1)->Arg(2);
BENCHMARK(BM_UpdateCurvedPath10kPlannedJumps)->Arg(1)->Arg(2);
BENCHMARK(BM_UpdateCurvedPath10kGoverned)->Arg(1)->Arg(2);
BENCHMARK(BM_UpdateCurvedPath10kShipped)->Arg(1)->Arg(2);
BENCHMARK(BM_UpdateCircleSectionsShipped)->Arg(2);
BENCHMARK(BM_UpdateCircleSectionsExactTarget)->Arg(2);
BENCHMARK(BM_UpdateCircleSectionsPlannedJumps)->Arg(2);
BENCHMARK(BM_UpdateCurvedPath10kPaperLaw)->Arg(1)->Arg(2);
BENCHMARK(BM_UpdateFarFromCurvedPath10k)->Arg(2)->Repetitions(3)->ReportAggregatesOnly(true);

}  // namespace
