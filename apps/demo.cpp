// smoothsteer demo: the C^1 controller (n = 2) brings a car from 40 m away, facing away from the
// path, onto a curved path (line - left arc - right arc - line) on the kinematic model, and writes
// the trace to demo_trace.csv (or the path given as the first argument), in the columns of
// `smoothsteer run`'s trace.csv, and the reference path to demo_trace_path.csv beside it; plot
// both with /usr/bin/python3 scripts/plot_trace.py demo_trace.csv.

#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>

#include "smoothsteer/io/trace_csv.hpp"
#include "smoothsteer/smoothsteer.hpp"

int main(int argc, char** argv) {
  using namespace smoothsteer;
  try {
    if (argc > 2 || (argc == 2 && argv[1][0] == '-')) {  // "--help" is no trace file name
      std::printf("usage: smoothsteer_demo [TRACE.csv]   (default demo_trace.csv)\n");
      return argc == 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") ? 0
                                                                                             : 1;
    }
    const std::string trace_path = argc > 1 ? argv[1] : "demo_trace.csv";
    auto path = std::make_shared<const Path>(PathBuilder({0.0, 0.0}, 0.0)
                                                 .line(30.0)
                                                 .arc(25.0, pi / 2.0)
                                                 .arc(40.0, -pi / 2.0)
                                                 .line(60.0)
                                                 .build());
    ControllerParameters parameters;  // n = 2, lambda_veh = 2.7 m, kbar_l = 0.2 1/m, k_rob = 0.3
    LeadWheelController controller(parameters, path);

    KinematicLoopOptions options;
    options.speed_mps = 8.0;
    options.duration_s = 40.0;
    const Pose2 start{{-10.0, -40.0}, -2.5};  // 40 m right of the path, heading away from it
    const KinematicLoopResult result = run_kinematic_closed_loop(controller, start, options);
    {  // run's trace.csv columns (io/trace_csv.hpp), through a temporary file and a rename
      io::TraceCsvWriter trace(trace_path + ".tmp");
      for (const KinematicTraceSample& sample : result.trace) {
        trace.write(kinematic_trace_sample(sample, result.options));
      }
      trace.close();
      std::filesystem::rename(trace_path + ".tmp", trace_path);
    }
    // The reference path beside the trace, for scripts/plot_trace.py: <trace>_path.csv.
    const std::string path_file =
        trace_path.substr(0, trace_path.size() - (trace_path.ends_with(".csv") ? 4 : 0)) +
        "_path.csv";
    {
      std::ofstream out(path_file);
      out.precision(9);
      out << "x,y\n";
      for (double s = 0.0; s <= path->length(); s += 0.25) {
        const PathPoint point = path->evaluate(s);
        out << point.position.x << ',' << point.position.y << '\n';
      }
      if (!out) throw std::runtime_error("cannot write " + path_file);
    }

    const ChainBounds& bounds = controller.bounds();
    std::printf("smoothsteer demo: n = %d, v = %.1f m/s, start 40 m off the path facing away\n",
                parameters.chain.order, options.speed_mps);
    std::printf("  status                     : %s\n", to_string(result.status));
    std::printf("  final |e| (rear axle)      : %.4f m\n", std::abs(result.final_lateral_error_m));
    std::printf("  max |delta_veh|            : %.4f rad (bound %.4f)\n",
                result.max_abs_steering_rad, bounds.steering_angle_rad);
    std::printf("  max |d delta_veh/dt|       : %.4f rad/s (bound %.4f)\n",
                result.max_abs_steering_rate_radps,
                bounds.steering_rate_per_meter * std::abs(options.speed_mps));
    std::printf("  max |d2 delta_veh/dt2|     : %.4f rad/s^2\n",
                result.max_abs_steering_acceleration_radps2);
    std::printf("  trace                      : %s (%zu rows), path %s\n", trace_path.c_str(),
                result.trace.size(), path_file.c_str());
    return result.status == Status::ok ? 0 : 1;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "smoothsteer_demo: %s\n", error.what());
    return 2;
  }
}
