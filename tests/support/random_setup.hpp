#pragma once
//! Random valid controller parameters and random reference paths for property tests.

#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "smoothsteer/controller/controller_parameters.hpp"
#include "smoothsteer/controller/trailer_chain.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/path/path.hpp"
#include "smoothsteer/path/path_builder.hpp"
#include "support/property.hpp"

namespace smoothsteer::testing {

//! Random valid parameters of order n whose real steering-angle bound is `steering_bound`.
inline ControllerParameters random_parameters(Random& random, int order, double steering_bound) {
  ControllerParameters p;
  p.chain.order = order;
  p.chain.vehicle_wheelbase_m = random.uniform(2.0, 4.0);
  p.law.k_rob = random.uniform(0.2, 0.6);
  for (int i = 0; i < order; ++i) {
    const auto k = static_cast<std::size_t>(i);
    p.chain.wheelbases_m[k] = i == 0 ? random.uniform(0.6, 1.0) * p.chain.vehicle_wheelbase_m
                                     : random.uniform(0.15, 0.8) * p.chain.vehicle_wheelbase_m;
  }
  // Bisection on kbar_n such that atan(lambda_veh kbar_0) = steering_bound.
  double low = 0.0;
  double high = order > 0 ? 1.0 / p.chain.wheelbases_m[static_cast<std::size_t>(order - 1)] : 10.0;
  for (int iteration = 0; iteration < 200; ++iteration) {
    p.chain.lead_curvature_bound = 0.5 * (low + high);
    const bool valid = p.validation_error().empty();
    if (valid && compute_chain_bounds(p).steering_angle_rad < steering_bound) {
      low = p.chain.lead_curvature_bound;
    } else {
      high = p.chain.lead_curvature_bound;
    }
  }
  p.chain.lead_curvature_bound = low;
  return p;
}

inline std::string describe(const ControllerParameters& p) {
  std::ostringstream text;
  text << "n=" << p.chain.order << " lambda_veh=" << p.chain.vehicle_wheelbase_m
       << " kbar_n=" << p.chain.lead_curvature_bound << " k_rob=" << p.law.k_rob << " wheelbases=[";
  for (int i = 0; i < p.chain.order; ++i)
    text << p.chain.wheelbases_m[static_cast<std::size_t>(i)] << ' ';
  text << ']';
  return text.str();
}

//! line, circle and waypoints are C2; line_arcs has curvature jumps at its joints.
enum class PathKind { line, circle, waypoints, line_arcs };

inline const char* to_string(PathKind kind) {
  switch (kind) {
    case PathKind::line:
      return "line";
    case PathKind::circle:
      return "circle";
    case PathKind::waypoints:
      return "waypoints";
    case PathKind::line_arcs:
      return "line_arcs";
  }
  return "?";
}

//! A random path whose curvature stays below max_curvature.
inline std::shared_ptr<const Path> random_path(Random& random, PathKind kind,
                                               double max_curvature) {
  switch (kind) {
    case PathKind::line:
      return std::make_shared<const Path>(
          Path::straight_line({random.uniform(-20.0, 20.0), random.uniform(-20.0, 20.0)},
                              random.uniform(-pi, pi), random.uniform(50.0, 200.0)));
    case PathKind::circle:
      return std::make_shared<const Path>(Path::circle({0.0, 0.0},
                                                       random.uniform(1.2, 3.0) / max_curvature,
                                                       random.coin(), random.uniform(-pi, pi)));
    case PathKind::waypoints: {
      for (double scale = 1.0;; scale *= 0.7) {
        std::vector<Vec2> points;
        Vec2 point{-60.0, random.uniform(-20.0, 20.0)};
        double heading = random.uniform(-0.5, 0.5);
        const double step = 5.0;
        for (int k = 0; k < 40; ++k) {
          points.push_back(point);
          heading += random.uniform(-1.0, 1.0) * scale * 0.5 * step * max_curvature;
          point = point + step * unit_from_heading(heading);
        }
        auto path = std::make_shared<const Path>(Path::from_waypoints(points));
        if (path->max_abs_curvature() <= max_curvature) return path;
      }
    }
    case PathKind::line_arcs: {  // a line, 2-4 arcs of random turn, a line
      PathBuilder builder({random.uniform(-20.0, 20.0), random.uniform(-20.0, 20.0)},
                          random.uniform(-pi, pi));
      builder.line(random.uniform(10.0, 40.0));
      const int arcs = random.integer(2, 4);
      for (int i = 0; i < arcs; ++i) {
        const double radius = random.uniform(1.0, 2.0) / max_curvature;
        builder.arc(radius, (random.coin() ? 1.0 : -1.0) * random.uniform(0.6, 1.6));
      }
      builder.line(random.uniform(20.0, 40.0));
      return std::make_shared<const Path>(builder.build());
    }
  }
  return nullptr;
}

}  // namespace smoothsteer::testing
