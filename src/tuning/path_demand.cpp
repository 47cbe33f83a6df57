#include "smoothsteer/tuning/path_demand.hpp"

#include "smoothsteer/controller/feedforward.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

namespace smoothsteer {

namespace {

//! Largest |f(s)| and |f'(s)| of a curvature profile sampled every spacing_m over [0, L].
PathDemand sampled_demand(const Path& path, double spacing_m,
                          const std::function<double(double)>& curvature_at) {
  PathDemand demand;
  const auto samples = static_cast<long>(std::ceil(path.length() / spacing_m));
  double previous = curvature_at(0.0);
  demand.max_curvature = std::abs(previous);
  for (long k = 1; k <= samples; ++k) {
    const double s = std::min(path.length(), static_cast<double>(k) * spacing_m);
    const double curvature = curvature_at(s);
    demand.max_curvature = std::max(demand.max_curvature, std::abs(curvature));
    demand.max_curvature_rate =
        std::max(demand.max_curvature_rate, std::abs(curvature - previous) / spacing_m);
    previous = curvature;
  }
  return demand;
}

void check_spacing(double spacing_m) {
  if (!std::isfinite(spacing_m) || spacing_m <= 0.0) {
    throw std::invalid_argument("path_demand: spacing_m = " + std::to_string(spacing_m) +
                                " must be finite and > 0");
  }
}

}  // namespace

PathDemand path_demand(const Path& path, double spacing_m) {
  check_spacing(spacing_m);
  PathDemand demand =
      sampled_demand(path, spacing_m, [&](double s) { return path.evaluate(s).curvature; });
  demand.max_curvature = std::max(demand.max_curvature, path.max_abs_curvature());
  return demand;
}

double lead_curvature_rate_demand(const Path& path, const double* wheelbases, int order) {
  if (order <= 0) return 0.0;
  constexpr double h = curvature_jet_step_m;
  const auto samples = static_cast<long>(std::ceil(path.length() / h));
  // Samples inside [0, L] only: the straight end extensions would add a jump that no vehicle
  // starting on the path meets.
  auto curvature = [&](long k) {
    return path
        .evaluate(std::min(path.length(), static_cast<double>(std::clamp(k, 0L, samples)) * h))
        .curvature;
  };
  double before = curvature(-1), at = curvature(0), demand = 0.0, previous = 0.0;
  for (long k = 0; k <= samples; ++k) {  // one path evaluation per sample
    const double after = curvature(k + 1);
    const double lead =
        invert_chain(curvature_jet(before, at, after), wheelbases, order).lead_curvature;
    if (k > 0) demand = std::max(demand, std::abs(lead - previous) / h);
    previous = lead, before = at, at = after;
  }
  return demand;
}

PathDemand apply_path_demand(TuningOptions& options, std::shared_ptr<const Path> path) {
  if (!path) return {};
  const PathDemand demand = path_demand(*path);
  options.path_curvature_bound = std::max(options.path_curvature_bound, demand.max_curvature);
  options.path_curvature_rate_bound =
      std::isinf(options.path_curvature_rate_bound)
          ? demand.max_curvature_rate
          : std::max(options.path_curvature_rate_bound, demand.max_curvature_rate);
  options.reference_path = std::move(path);
  return demand;
}

}  // namespace smoothsteer
