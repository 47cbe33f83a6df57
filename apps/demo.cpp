// smoothsteer demo: the car's SteeringSystem, built from vehicles/passenger_car.yaml and its
// steering actuator (make_steering_system, docs/steering_system.md), drives the kinetic
// single-track model (Magic-Formula tires) behind that actuator over a short road: a lane change,
// then a curve, started 0.5 m off the path with a 0.1 rad heading error. It prints the car's
// three steering limits beside the held command's maxima and writes
//   TRACE.csv             the trace, in the columns of `smoothsteer run`'s trace.csv,
//   TRACE_path.csv        the reference path,
//   TRACE_limits.json     the car's limits and the figure's title,
// for scripts/plot_trace.py, which scripts/demo.sh then runs to draw TRACE.png.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>

#include "smoothsteer/io/trace_csv.hpp"
#include "smoothsteer/io/vehicle_file.hpp"
#include "smoothsteer/smoothsteer.hpp"
#include "smoothsteer/tuning/vehicle_steering_system.hpp"

namespace {

using namespace smoothsteer;

constexpr double speed_mps = 10.0;
const Pose2 start{{-10.0, -0.5}, 0.1};  // rear axle 0.5 m right of the path, 0.1 rad to the left
constexpr double settle_time_s = 2.0;   // the engagement from the start is over by then

//! 30 m straight (the car starts 10 m in), a lane change of 3.5 m to the left over 48 m (clothoids:
//! curvature up to 1/82 m), 20 m straight, a left curve of radius 40 m through about 80 degrees, 30
//! m straight.
Path demo_road() {
  return PathBuilder({-20.0, 0.0}, 0.0)
      .line(30.0)
      .clothoid(12.0, 0.0122)
      .clothoid(24.0, -0.0122)
      .clothoid(12.0, 0.0)
      .line(20.0)
      .clothoid(15.0, 1.0 / 40.0)
      .arc(40.0, 1.0)
      .clothoid(15.0, 0.0)
      .line(30.0)
      .build();
}

//! vehicles/passenger_car.yaml in the working directory (scripts/demo.sh runs in the source
//! tree), else in the source tree the demo was built from.
std::string vehicle_file() {
  const std::string relative = "vehicles/passenger_car.yaml";
  if (std::filesystem::exists(relative)) return relative;
  return std::string(SMOOTHSTEER_SOURCE_DIR) + "/" + relative;
}

//! Largest |e| (rear axle) from `time_s` on: the lane change and the curve, past the engagement.
double max_abs_error_from(const SimulationResult& result, double time_s) {
  double largest = 0.0;
  for (const TraceSample& sample : result.trace) {
    if (sample.time_s >= time_s) largest = std::max(largest, std::abs(sample.lateral_error_m));
  }
  return largest;
}

std::string stem_of(const std::string& trace_path) {
  return trace_path.substr(0, trace_path.size() - (trace_path.ends_with(".csv") ? 4 : 0));
}

void write_trace(const SimulationResult& result, const std::string& trace_path) {
  io::TraceCsvWriter trace(trace_path + ".tmp");  // a temporary file and a rename
  for (const TraceSample& sample : result.trace) trace.write(sample);
  trace.close();
  std::filesystem::rename(trace_path + ".tmp", trace_path);
}

void write_path(const Path& path, const std::string& file) {
  std::ofstream out(file);
  out.precision(9);
  out << "x,y\n";
  for (double s = 0.0; s <= path.length(); s += 0.25) {
    const PathPoint point = path.evaluate(s);
    out << point.position.x << ',' << point.position.y << '\n';
  }
  if (!out) throw std::runtime_error("cannot write " + file);
}

void write_limits(const VehicleParameters& vehicle, const std::string& file) {
  std::ofstream out(file);
  out.precision(9);
  out << "{\"title\": \"passenger_car: SteeringSystem on the kinetic model, " << speed_mps
      << " m/s\",\n \"max_steering_angle_rad\": " << vehicle.max_steering_angle_rad
      << ",\n \"max_steering_rate_radps\": " << vehicle.max_steering_rate_radps
      << ",\n \"max_steering_acceleration_radps2\": " << vehicle.max_steering_acceleration_radps2
      << "}\n";
  if (!out) throw std::runtime_error("cannot write " + file);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace smoothsteer;
  try {
    if (argc > 2 || (argc == 2 && argv[1][0] == '-')) {  // "--help" is no trace file name
      std::printf("usage: smoothsteer_demo [TRACE.csv]   (default demo_trace.csv)\n");
      return argc == 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") ? 0
                                                                                             : 1;
    }
    const std::string trace_path = argc > 1 ? argv[1] : "demo_trace.csv";
    const auto path = std::make_shared<const Path>(demo_road());

    VehicleDescription car;
    car.vehicle = io::load_vehicle_file(vehicle_file());
    car.actuator.max_angle_rad = car.vehicle.max_steering_angle_rad;  // 10 Hz, 10 ms dead time
    car.actuator.max_rate_radps = car.vehicle.max_steering_rate_radps;
    SteeringSystemOptions options;
    options.max_speed_mps = 15.0;
    SteeringSystem system = make_steering_system(car, path, options);  // set-up: may throw

    const DynamicSingleTrack plant(car.vehicle);
    SpeedProfile speed;
    speed.initial_speed_mps = speed.final_speed_mps = speed_mps;
    SimulationParameters simulation;
    simulation.duration_s = 30.0;
    const SimulationResult result =
        simulate(*path, plant, car.actuator, speed, simulation, start, system);

    MetricsParameters limits;
    limits.steering_angle_limit_rad = car.vehicle.max_steering_angle_rad;
    limits.steering_rate_limit_radps = car.vehicle.max_steering_rate_radps;
    limits.steering_acceleration_limit_radps2 = car.vehicle.max_steering_acceleration_radps2;
    const Metrics m = compute_metrics(result.trace, limits);

    write_trace(result, trace_path);
    const std::string stem = stem_of(trace_path);
    write_path(*path, stem + "_path.csv");
    write_limits(car.vehicle, stem + "_limits.json");

    std::printf(
        "smoothsteer demo: the passenger car's SteeringSystem (vehicles/passenger_car.yaml and "
        "its actuator)\n  on the kinetic single-track model at %.1f m/s: a lane change, then a "
        "curve, from 0.5 m and 0.1 rad off the path\n",
        speed_mps);
    std::printf("  stop                       : %s (%d steps, %.1f s)\n",
                result.stop_reason.c_str(), m.steps, m.duration_s);
    std::printf(
        "  max |e| (rear axle)        : %.4f m at the start; %.4f m from t = %.0f s on (lane "
        "change, curve)\n",
        m.max_abs_rear_error_m, max_abs_error_from(result, settle_time_s), settle_time_s);
    std::printf("  the held command against the car's limits:\n");
    std::printf("  steering angle             : max %.4f rad      limit %.4f rad\n",
                m.max_abs_command_rad, car.vehicle.max_steering_angle_rad);
    std::printf("  steering rate              : max %.4f rad/s    limit %.4f rad/s\n",
                m.held_rate_max_radps, car.vehicle.max_steering_rate_radps);
    std::printf("  steering acceleration      : max %.4f rad/s^2  limit %.4f rad/s^2\n",
                m.held_acceleration_max_radps2, car.vehicle.max_steering_acceleration_radps2);
    std::printf("  trace                      : %s (%zu rows), path %s_path.csv\n",
                trace_path.c_str(), result.trace.size(), stem.c_str());
    const bool ok = result.status == Status::ok && !result.non_finite;
    return ok ? 0 : 1;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "smoothsteer_demo: %s\n", error.what());
    return 2;
  }
}
