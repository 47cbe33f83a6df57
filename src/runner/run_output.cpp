#include "smoothsteer/runner/run_output.hpp"

#include <cmath>
#include <fstream>
#include <stdexcept>

#include "smoothsteer/io/trace_csv.hpp"

namespace smoothsteer::runner {
using io::OutputDirectory;
using io::TraceCsvWriter;
namespace {

//! Counts are written as JSON integers, every other metric as a number (null if not finite).
bool is_count(const std::string& name) {
  const std::string suffix = "_violations";
  return name == "steps" || name == "non_finite_values" ||
         (name.size() > suffix.size() &&
          name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0);
}

void write_summary(const std::filesystem::path& file, const Scenario& scenario,
                   const RunResult& result) {
  // Text was validated as UTF-8 when read; `replace` keeps a stray byte from failing the dump.
  const std::string text =
      summary_json(scenario, result).dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
  std::ofstream out(file, std::ios::binary);
  out << text << '\n';
  out.flush();
  if (!out) throw std::runtime_error(file.string() + ": writing the summary failed");
}

}  // namespace

std::string tool_version() {
  return SMOOTHSTEER_VERSION;
}

std::string tool_commit() {
  return SMOOTHSTEER_COMMIT;
}

nlohmann::json summary_json(const Scenario& scenario, const RunResult& result) {
  nlohmann::json summary;
  summary["tool"] = {
      {"name", "smoothsteer"}, {"version", tool_version()}, {"commit", tool_commit()}};
  summary["scenario"] = scenario.name;
  summary["scenario_file"] = scenario.file;
  summary["description"] = scenario.description;
  summary["controller"] = result.controller_name;
  summary["model"] = scenario.model;
  summary["vehicle"] = scenario.vehicle_name;
  summary["vehicle_source"] = scenario.vehicle_source;
  summary["status"] = to_string(result.simulation.status);
  summary["stop_reason"] = result.simulation.stop_reason;
  summary["model_evaluations"] = result.simulation.model_evaluations;
  summary["overrides"] = scenario.overrides;
  nlohmann::json metrics = nlohmann::json::object();
  for (const auto& [name, value] : metric_values(result.metrics)) {
    if (!std::isfinite(value)) {
      metrics[name] = nullptr;
    } else if (is_count(name)) {
      metrics[name] = static_cast<long long>(value);
    } else {
      metrics[name] = value;
    }
  }
  metrics["reached"] = result.metrics.reached;
  summary["metrics"] = metrics;
  summary["parameters"] = scenario.parameters;
  return summary;
}

RunResult run_scenario(const Scenario& scenario, OutputDirectory& out) {
  const std::unique_ptr<SteeringController> controller = make_controller(scenario);
  TraceCsvWriter trace(out.file("trace.csv").string());
  MetricsAccumulator metrics(scenario.metrics);
  RunResult result;
  const TraceObserver observer = [&](const TraceSample& sample) {
    trace.write(sample);
    metrics.add(sample);
  };
  result.simulation = simulate_scenario(scenario, *controller, observer);
  trace.close();
  result.metrics = metrics.result();
  result.controller_name = controller->name();
  write_summary(out.file("summary.json"), scenario, result);
  return result;
}

void write_run_outputs(const std::string& directory, const Scenario& scenario,
                       const RunResult& result) {
  OutputDirectory out(directory, "output directory");
  {
    TraceCsvWriter trace(out.file("trace.csv").string());
    for (const TraceSample& sample : result.simulation.trace) trace.write(sample);
    trace.close();
  }
  write_summary(out.file("summary.json"), scenario, result);
  out.commit();
}

}  // namespace smoothsteer::runner
