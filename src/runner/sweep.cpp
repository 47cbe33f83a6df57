#include "smoothsteer/runner/sweep.hpp"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <sstream>
#include <thread>

#include "smoothsteer/runner/progress.hpp"

namespace smoothsteer::runner {
using io::ConfigError;
namespace {

std::string key_of(const std::string& override_text) {
  return override_text.substr(0, override_text.find('='));
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char ch : text) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return quoted + "\"";
}

}  // namespace

SweepAxis parse_sweep_axis(const std::string& text) {
  const std::size_t equals = text.find('=');
  if (equals == std::string::npos || equals == 0 || equals + 1 == text.size()) {
    throw ConfigError("--vary '" + text + "': expected key.path=v1,v2,...");
  }
  SweepAxis axis{text.substr(0, equals), {}};
  std::stringstream values(text.substr(equals + 1));
  std::string value;
  while (std::getline(values, value, ',')) {
    if (value.empty()) throw ConfigError("--vary '" + text + "': empty value");
    axis.values.push_back(value);
  }
  return axis;
}

std::vector<std::vector<std::string>> sweep_grid(const std::vector<SweepAxis>& axes) {
  // Count first: 30 axes of 2 values are 2^30 rows (an input-controlled count must be capped before
  // anything is allocated).
  double rows = 1.0;
  for (const SweepAxis& axis : axes) rows *= static_cast<double>(axis.values.size());
  if (rows > static_cast<double>(max_sweep_rows)) {
    throw ConfigError("--vary: the " + std::to_string(axes.size()) + " axes give " +
                      std::to_string(static_cast<long double>(rows)) + " runs; at most " +
                      std::to_string(max_sweep_rows) + " are allowed");
  }
  std::vector<std::vector<std::string>> sets{{}};
  for (const SweepAxis& axis : axes) {
    std::vector<std::vector<std::string>> next;
    for (const auto& set : sets) {
      for (const std::string& value : axis.values) {
        auto extended = set;
        extended.push_back(axis.key + "=" + value);
        next.push_back(std::move(extended));
      }
    }
    sets = std::move(next);
  }
  return sets;
}

std::vector<std::vector<std::string>> paper_variations(const Scenario& base) {
  const nlohmann::json& c = base.parameters.at("controller");
  if (c.value("type", "") != "lead_wheel" || !c.contains("lead_wheelbase_m")) {
    throw ConfigError(base.file +
                      ": key 'controller': the paper variations need a lead_wheel "
                      "controller with lead_wheelbase_m");
  }
  auto set = [](const std::string& key, double value) {
    std::ostringstream text;
    text.precision(12);
    text << "controller." << key << "=" << value;
    return text.str();
  };
  const double kbar = c.at("lead_curvature_bound").get<double>();
  const double lead = c.at("lead_wheelbase_m").get<double>();
  const double k_rob = c.at("k_rob").get<double>();
  return {{set("lead_curvature_bound", kbar)},
          {set("lead_curvature_bound", 0.5 * kbar)},
          {set("lead_wheelbase_m", 4.0 * lead)},
          {set("k_rob", k_rob * (1.0 - 1.0 / 3.0))}};
}

void run_parallel(std::size_t count, int threads, const std::function<void(std::size_t)>& task,
                  const std::function<void(int, int)>& progress) {
  std::atomic<std::size_t> next{0};
  std::atomic<int> done{0};
  std::mutex progress_mutex;
  const int total = static_cast<int>(count);
  progress_expect(count);
  auto worker = [&] {
    for (std::size_t i = next++; i < count && !progress_stop_requested(); i = next++) {
      task(i);
      progress_case_done();
      const int finished = ++done;
      if (progress) {
        std::lock_guard lock(progress_mutex);
        progress(finished, total);
      }
    }
  };
  unsigned workers = threads > 0 ? static_cast<unsigned>(threads)
                                 : std::max(1u, std::thread::hardware_concurrency());
  workers = std::min<unsigned>(workers, static_cast<unsigned>(std::max<std::size_t>(count, 1)));
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < workers; ++t) pool.emplace_back(worker);
  for (std::thread& thread : pool) thread.join();
  throw_if_interrupted("the parallel runs were");
}

std::vector<SweepRow> run_sweep(const std::string& scenario_file,
                                const std::vector<std::string>& base_overrides,
                                const std::vector<std::vector<std::string>>& sets, int threads,
                                const std::function<void(int, int)>& progress) {
  std::vector<SweepRow> rows(sets.size());
  auto run_row = [&](std::size_t i) {
    SweepRow& row = rows[i];
    row.overrides = sets[i];
    try {
      std::vector<std::string> overrides = base_overrides;
      overrides.insert(overrides.end(), sets[i].begin(), sets[i].end());
      const Scenario scenario = load_scenario(scenario_file, overrides);
      const RunResult result = run_scenario(scenario);
      row.metrics = result.metrics;
      row.ok = result.simulation.status == Status::ok && !result.simulation.non_finite;
      if (!row.ok) {
        row.error = "run stopped: " + result.simulation.stop_reason + " (" +
                    result.simulation.stop_detail + ")";
      }
    } catch (const std::exception& error) {
      row.error = error.what();
    }
  };
  run_parallel(sets.size(), threads, run_row, progress);
  return rows;
}

std::string sweep_csv(const std::vector<SweepRow>& rows) {
  std::vector<std::string> keys;
  for (const SweepRow& row : rows) {
    for (const std::string& o : row.overrides) {
      if (std::find(keys.begin(), keys.end(), key_of(o)) == keys.end()) keys.push_back(key_of(o));
    }
  }
  std::ostringstream out;
  out.precision(9);
  for (const std::string& key : keys) out << csv_field(key) << ',';
  out << "ok,error";
  for (const auto& [name, value] : metric_values(Metrics{})) out << ',' << name;
  out << '\n';
  for (const SweepRow& row : rows) {
    for (const std::string& key : keys) {
      std::string value;
      for (const std::string& o : row.overrides) {
        if (key_of(o) == key) value = o.substr(o.find('=') + 1);
      }
      out << csv_field(value) << ',';
    }
    out << (row.ok ? 1 : 0) << ',' << csv_field(row.error);
    for (const auto& [name, value] : metric_values(row.metrics)) out << ',' << value;
    out << '\n';
  }
  return out.str();
}

}  // namespace smoothsteer::runner
