// Path, PathBuilder, PathPoint, PathProjection (include/smoothsteer/path/).

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include "bindings.hpp"
#include "smoothsteer/path/path.hpp"
#include "smoothsteer/path/path_builder.hpp"
#include "smoothsteer/path/waypoint_conditioner.hpp"
#include "smoothsteer/path/waypoint_jitter.hpp"

namespace smoothsteer::python {

std::vector<Vec2> waypoints_from(
    const py::array_t<double, py::array::c_style | py::array::forcecast>& points,
    const char* where) {
  if (points.ndim() != 2 || points.shape(1) != 2) {
    throw py::value_error(std::string(where) + ": waypoints must be an N x 2 array of x, y [m]");
  }
  std::vector<Vec2> waypoints(static_cast<std::size_t>(points.shape(0)));
  const auto view = points.unchecked<2>();
  for (py::ssize_t i = 0; i < points.shape(0); ++i) {
    waypoints[static_cast<std::size_t>(i)] = {view(i, 0), view(i, 1)};
  }
  return waypoints;
}

namespace {

//! evaluate() on an array of arc lengths: N x 4 columns x, y, heading, curvature.
py::array_t<double> sample(const Path& path, const py::array_t<double, py::array::forcecast>& s) {
  const auto input = s.unchecked();
  py::array_t<double> result({input.size(), py::ssize_t{4}});
  auto out = result.mutable_unchecked<2>();
  const double* values = s.data();
  for (py::ssize_t i = 0; i < input.size(); ++i) {
    const PathPoint point = path.evaluate(values[i]);
    out(i, 0) = point.position.x;
    out(i, 1) = point.position.y;
    out(i, 2) = point.heading_rad;
    out(i, 3) = point.curvature;
  }
  return result;
}

}  // namespace

void bind_path(py::module_& m) {
  using WC = WaypointConditioner;
  py::class_<WC::Parameters>(m, "WaypointConditionerParameters",
                             "WaypointConditioner's settings; keyword arguments.")
      .def(py::init(&from_keywords<WC::Parameters>))
      .def_readwrite("memory_windows", &WC::Parameters::memory_windows,
                     "windows the pooled jitter estimate remembers, [1, 1e6]")
      .def_readwrite("tolerance_m", &WC::Parameters::tolerance_m,
                     "the least tolerance each window is fitted with [m], [0, 10]")
      .def_readwrite("history_m", &WC::Parameters::history_m,
                     "how far behind a jittered window's start the earlier windows' waypoints "
                     "are fitted with it [m], [0, 1000]; 0 fits each window alone")
      .def("validate", &WC::Parameters::validate);
  py::class_<WC>(m, "WaypointConditioner",
                 "A stack's trajectory windows fitted one after another at the jitter pooled "
                 "over them (docs/controller.md, \"Paths as they come\"): keep one per planner "
                 "and hand each window's Path to SteeringSystem.set_path().")
      .def(py::init([](const WC::Parameters& p) { return WC(p); }),
           py::arg("parameters") = WC::Parameters{})
      .def(
          "fit",
          [](WC& self, const py::array_t<double, py::array::c_style | py::array::forcecast>& xy) {
            return std::make_shared<Path>(self.fit(waypoints_from(xy, "WaypointConditioner.fit")));
          },
          py::arg("waypoints"),
          "Pools the window's (N x 2 array x, y [m]) jitter and fits it at sqrt(2) times the "
          "pooled jitter (at least parameters.tolerance_m): a Path.")
      .def_property_readonly("jitter_m", &WC::jitter_m, "the pooled jitter per coordinate [m]")
      .def_property_readonly("tolerance_m", &WC::tolerance_m,
                             "the tolerance the last window was fitted with [m]")
      .def_property_readonly("windows", &WC::windows, "windows pooled so far")
      .def_property_readonly("parameters", &WC::parameters)
      .def("reset", &WC::reset, "forgets the estimate (another planner)");
  m.def(
      "estimate_waypoint_jitter",
      [](const py::array_t<double, py::array::c_style | py::array::forcecast>& xy) {
        return estimate_waypoint_jitter(waypoints_from(xy));
      },
      py::arg("waypoints"),
      "The jitter's standard deviation per coordinate [m] read from an N x 2 array of waypoints "
      "sampled from lines, arcs and clothoids; 0 for clean ones or fewer than 20 points.");
  py::class_<PathPoint>(m, "PathPoint", "A point on the path.")
      .def_property_readonly(
          "position", [](const PathPoint& p) { return py::make_tuple(p.position.x, p.position.y); },
          "(x, y) [m]")
      .def_readonly("heading_rad", &PathPoint::heading_rad, "tangent direction [rad]")
      .def_readonly("curvature", &PathPoint::curvature, "[1/m], positive turning left")
      .def("__repr__", [](const PathPoint& p) {
        return "PathPoint(x=" + std::to_string(p.position.x) +
               ", y=" + std::to_string(p.position.y) +
               ", heading_rad=" + std::to_string(p.heading_rad) +
               ", curvature=" + std::to_string(p.curvature) + ")";
      });

  py::class_<PathProjection>(m, "PathProjection", "Closest point of the path to a point.")
      .def_readonly("arc_length_m", &PathProjection::arc_length_m, "s of the closest point [m]")
      .def_readonly("lateral_error_m", &PathProjection::lateral_error_m,
                    "signed distance, left of the path positive [m]")
      .def_readonly("heading_rad", &PathProjection::heading_rad, "path tangent there [rad]")
      .def_readonly("curvature", &PathProjection::curvature, "path curvature there [1/m]")
      .def_property_readonly(
          "closest_point",
          [](const PathProjection& p) {
            return py::make_tuple(p.closest_point.x, p.closest_point.y);
          },
          "(x, y) [m]");

  py::class_<Path, std::shared_ptr<Path>>(m, "Path",
                                          "A reference path (lines, arcs, circles, C2 splines). "
                                          "Arc length s [m] starts at 0; e is positive left.")
      .def_static(
          "from_waypoints",
          [](const py::array_t<double, py::array::c_style | py::array::forcecast>& xy,
             double smoothing_tolerance_m, bool estimate_jitter, bool restore_corners) {
            return std::make_shared<Path>(Path::from_waypoints(
                waypoints_from(xy),
                WaypointSmoothing{smoothing_tolerance_m, estimate_jitter, restore_corners}));
          },
          py::arg("waypoints"), py::arg("smoothing_tolerance_m") = 0.0,
          py::arg("estimate_jitter") = true, py::arg("restore_corners") = true,
          "C2 spline through an N x 2 array of waypoints x, y [m]: the smoothest C2 spline whose "
          "knots stay an RMS distance from the waypoints, the larger of smoothing_tolerance_m "
          "and (estimate_jitter) sqrt(2) times the jitter estimate_waypoint_jitter() reads from "
          "them. Clean waypoints are interpolated exactly; estimate_jitter=False with "
          "smoothing_tolerance_m=0 always interpolates. restore_corners: where the fit bends "
          "tighter than a 50 m radius at a tolerance of at least 0.014 m, the fit of its residual "
          "is added (twicing), which restores the corner the smoothing cut.")
      .def_static(
          "circle",
          [](const py::object& center, double radius_m, bool counter_clockwise,
             double start_angle_rad) {
            return std::make_shared<Path>(Path::circle(to_vec2(center, "center"), radius_m,
                                                       counter_clockwise, start_angle_rad));
          },
          py::arg("center"), py::arg("radius_m"), py::arg("counter_clockwise") = true,
          py::arg("start_angle_rad") = 0.0,
          "A closed circle of radius_m [m] around center (x, y) [m], starting at the "
          "point at start_angle_rad [rad]; counter_clockwise turns left.")
      .def_static(
          "straight_line",
          [](const py::object& start, double heading_rad, double length_m) {
            return std::make_shared<Path>(
                Path::straight_line(to_vec2(start, "start"), heading_rad, length_m));
          },
          py::arg("start"), py::arg("heading_rad"), py::arg("length_m") = 100.0,
          "A line from start (x, y) [m] along heading_rad [rad], length_m [m] long; both "
          "ends extend along the tangent.")
      .def_property_readonly("length_m", &Path::length, "length [m]")
      .def_property_readonly("is_closed", &Path::is_closed)
      .def_property_readonly("segment_count", &Path::segment_count)
      .def_property_readonly("max_abs_curvature", &Path::max_abs_curvature,
                             "largest |curvature| [1/m]")
      .def_property_readonly(
          "curvature_jumps",
          [](const Path& path) {
            std::vector<std::tuple<double, double, double>> jumps;
            for (const Path::CurvatureJump& j : path.curvature_jumps())
              jumps.emplace_back(j.arc_length_m, j.before, j.after);
            return jumps;
          },
          "the steps of the curvature (s [m], before, after [1/m]): the planned jumps' input")
      .def_property_readonly(
          "curvature_kinks",
          [](const Path& path) {
            std::vector<std::tuple<double, double, double>> kinks;
            for (const Path::CurvatureKink& k : path.curvature_kinks())
              kinks.emplace_back(k.arc_length_m, k.before, k.after);
            return kinks;
          },
          "the steps of the curvature's slope at line, arc and clothoid joints (s [m], before, "
          "after [1/m^2]): the planned kinks' input (docs/feedforward.md, section 2b)")
      .def_property_readonly("max_abs_curvature_kink", &Path::max_abs_curvature_kink,
                             "the largest step of curvature_kinks [1/m^2], 0 without kinks")
      .def_property_readonly(
          "max_abs_spline_kink", &Path::max_abs_spline_kink,
          "on a path with spline pieces: the largest step of the curvature's slope across 2 m, "
          "read through the spline's ringing (docs/feedforward.md, 'Kinks a spline spreads') "
          "[1/m^2]; 0 on lines, arcs and clothoids")
      .def_property_readonly("curvature_sample_spacing_m", &Path::curvature_sample_spacing_m,
                             "spacing of the curvature samples the feedforward's preview reads [m]")
      .def_property_readonly(
          "curvature_samples",
          [](const Path& path) {
            const std::span<const double> samples = path.curvature_samples();
            py::array_t<double> result(static_cast<py::ssize_t>(samples.size()));
            std::copy(samples.begin(), samples.end(), result.mutable_data());
            return result;
          },
          "the curvature samples [1/m], sample i at s = i curvature_sample_spacing_m (a copy)")
      .def("curvature_sample", &Path::curvature_sample, py::arg("index"),
           "sample i [1/m], wrapped if closed, 0 outside [0, length] on open paths")
      .def("sampled_curvature", &Path::sampled_curvature, py::arg("arc_length_m"),
           "the sample nearest to arc length s [1/m]")
      .def("evaluate", &Path::evaluate, py::arg("arc_length_m"),
           "PathPoint at arc length s [m] (wrapped if closed, extended along the tangent if open).")
      .def("sample", &sample, py::arg("arc_length_m"),
           "evaluate() on an array of arc lengths [m]: an N x 4 array of x [m], y [m], heading "
           "[rad], curvature [1/m].")
      .def(
          "project",
          [](const Path& path, const py::object& point) {
            return path.project(to_vec2(point, "point"));
          },
          py::arg("point"), "Global closest-point projection of (x, y) [m]: a PathProjection.");

  py::class_<PathBuilder>(
      m, "PathBuilder",
      "Builds a path of lines, arcs and clothoids piece by piece from a start pose: "
      "PathBuilder((0, 0), 0.0).line(10).arc(5, pi / 2).build().")
      .def(py::init([](const py::object& start, double heading_rad) {
             return PathBuilder(to_vec2(start, "start"), heading_rad);
           }),
           py::arg("start"), py::arg("heading_rad"), "start (x, y) [m], heading [rad]")
      .def("line", &PathBuilder::line, py::arg("length_m"),
           py::return_value_policy::reference_internal, "Appends a straight piece of length_m [m].")
      .def("arc", &PathBuilder::arc, py::arg("radius_m"), py::arg("angle_rad"),
           py::return_value_policy::reference_internal,
           "Appends an arc of radius_m [m] turning by angle_rad [rad] (> 0 left).")
      .def("clothoid", &PathBuilder::clothoid, py::arg("length_m"), py::arg("curvature_end"),
           py::return_value_policy::reference_internal,
           "Appends a clothoid of length_m [m] whose curvature runs linearly from the current "
           "end curvature to curvature_end [1/m] (> 0 left).")
      .def(
          "build",
          [](const PathBuilder& builder, bool closed) {
            return std::make_shared<Path>(builder.build(closed));
          },
          py::arg("closed") = false, "The Path of the pieces so far.");
}

}  // namespace smoothsteer::python
