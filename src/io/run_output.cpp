#include "smoothsteer/io/run_output.hpp"

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace smoothsteer::io {

void write_file_atomically(const std::string& path, const std::string& content) {
  static std::atomic<unsigned long> counter{0};
  std::ostringstream name;
  name << path << ".tmp." << std::hash<std::thread::id>{}(std::this_thread::get_id()) << "."
       << counter++;
  const std::string temporary = name.str();
  {
    std::ofstream file(temporary, std::ios::binary);
    if (!file) throw std::runtime_error("cannot open '" + temporary + "' for writing");
    file << content;
    file.flush();
    if (!file) {
      file.close();
      std::remove(temporary.c_str());
      throw std::runtime_error("failed while writing '" + temporary + "'");
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot rename '" + temporary + "' to '" + path + "'");
  }
}

const std::vector<std::string>& trace_columns() {
  static const std::vector<std::string> columns(trace_column_names().begin(),
                                                trace_column_names().end());
  return columns;
}

std::string trace_csv(const SimulationResult& result) {
  std::ostringstream out;
  out.precision(9);
  const auto& columns = trace_columns();
  for (std::size_t i = 0; i < columns.size(); ++i) out << (i ? "," : "") << columns[i];
  out << '\n';
  for (const TraceSample& s : result.trace) {
    const auto values = trace_row(s);
    for (std::size_t i = 0; i < std::size(values); ++i) out << (i ? "," : "") << values[i];
    out << '\n';
  }
  return out.str();
}

nlohmann::json summary_json(const Scenario& scenario, const RunResult& result) {
  nlohmann::json summary;
  summary["scenario"] = scenario.name;
  summary["scenario_file"] = scenario.file;
  summary["description"] = scenario.description;
  summary["controller"] = result.controller_name;
  summary["model"] = scenario.model;
  summary["vehicle"] = scenario.vehicle_name;
  summary["vehicle_source"] = scenario.vehicle_source;
  summary["status"] = to_string(result.simulation.status);
  summary["stop_reason"] = result.simulation.stop_reason;
  summary["overrides"] = scenario.overrides;
  nlohmann::json metrics = nlohmann::json::object();
  for (const auto& [name, value] : metric_values(result.metrics)) {
    metrics[name] = std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
  }
  metrics["reached"] = result.metrics.reached;
  summary["metrics"] = metrics;
  summary["parameters"] = scenario.parameters;
  return summary;
}

void write_run_outputs(const std::string& directory, const Scenario& scenario,
                       const RunResult& result) {
  std::filesystem::create_directories(directory);
  const std::filesystem::path dir(directory);
  write_file_atomically((dir / "trace.csv").string(), trace_csv(result.simulation));
  write_file_atomically((dir / "summary.json").string(),
                        summary_json(scenario, result).dump(2) + "\n");
}

}  // namespace smoothsteer::io
