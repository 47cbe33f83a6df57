// Gear changes and the kinematic car (include/smoothsteer/path/path_plan.hpp,
// controller/cusp_sequencer.hpp, vehicle/kinematic_single_track.hpp).

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <vector>

#include "bindings.hpp"
#include "smoothsteer/controller/cusp_sequencer.hpp"
#include "smoothsteer/path/path_plan.hpp"
#include "smoothsteer/vehicle/kinematic_single_track.hpp"

namespace smoothsteer::python {

void bind_cusps(py::module_& m) {
  py::class_<KinematicSingleTrack>(m, "KinematicSingleTrack",
                                   "Kinematic bicycle model, rear axle as reference (eq. kappar).")
      .def(py::init<double>(), py::arg("wheelbase_m") = 2.7, "lambda_veh [m]")
      .def_readwrite("wheelbase_m", &KinematicSingleTrack::wheelbase_m, "[m]")
      .def(
          "step",
          [](const KinematicSingleTrack& car, const py::object& position, double heading_rad,
             double steering_angle_rad, double speed_mps, double dt_s) {
            const Pose2 next = car.step({to_vec2(position, "position"), heading_rad},
                                        steering_angle_rad, speed_mps, dt_s);
            return py::make_tuple(py::make_tuple(next.position.x, next.position.y),
                                  next.heading_rad);
          },
          py::arg("position"), py::arg("heading_rad"), py::arg("steering_angle_rad"),
          py::arg("speed_mps"), py::arg("dt_s"),
          "Exact step for constant steering [rad] and speed [m/s] over dt [s]: returns "
          "((x, y) [m], heading [rad]).");

  py::enum_<Gear>(m, "Gear").value("forward", Gear::forward).value("reverse", Gear::reverse);

  py::class_<PathPlan>(m, "PathPlan", "Pieces driven forwards or in reverse, meeting at cusps.")
      .def_static(
          "from_pieces",
          [](const std::vector<std::pair<std::shared_ptr<Path>, Gear>>& pieces) {
            std::vector<PathPiece> converted;
            for (const auto& [path, gear] : pieces) converted.push_back({path, gear});
            return PathPlan::from_pieces(std::move(converted));
          },
          py::arg("pieces"),
          "[(Path, Gear), ...]: each path runs in the direction of travel and starts "
          "within 1 mm of the previous end.")
      .def_static(
          "from_waypoints",
          [](const py::array_t<double, py::array::c_style | py::array::forcecast>& xy,
             const std::vector<int>& directions) {
            if (xy.ndim() != 2 || xy.shape(1) != 2) {
              throw py::value_error("PathPlan.from_waypoints: waypoints must be N x 2");
            }
            std::vector<Vec2> points;
            const auto view = xy.unchecked<2>();
            for (py::ssize_t i = 0; i < xy.shape(0); ++i) {
              points.push_back({view(i, 0), view(i, 1)});
            }
            return PathPlan::from_waypoints(points, directions);
          },
          py::arg("waypoints"), py::arg("directions"),
          "N x 2 waypoints [m] and the gear (+1 / -1) from each to the next.")
      .def_property_readonly("piece_count", &PathPlan::piece_count)
      .def_property_readonly("cusp_count", &PathPlan::cusp_count)
      .def(
          "piece_path",
          [](const PathPlan& plan, std::size_t index) {
            if (index >= plan.piece_count()) throw py::index_error("piece index out of range");
            return std::const_pointer_cast<Path>(plan.piece(index).path);
          },
          py::arg("index"))
      .def(
          "piece_gear",
          [](const PathPlan& plan, std::size_t index) {
            if (index >= plan.piece_count()) throw py::index_error("piece index out of range");
            return plan.piece(index).gear;
          },
          py::arg("index"))
      .def_property_readonly("final_position",
                             [](const PathPlan& plan) {
                               const Vec2 p = plan.final_position();
                               return py::make_tuple(p.x, p.y);
                             })
      .def_property_readonly("final_vehicle_heading_rad", &PathPlan::final_vehicle_heading_rad);

  py::class_<CuspSequencer>(m, "CuspSequencer",
                            "Drives a PathPlan: hands each piece to the controller and gives a "
                            "speed that stops at every cusp.")
      .def(py::init([](const PathPlan& plan, SteeringController& controller,
                       double cruise_speed_mps, double deceleration_mps2) {
             CuspSpeedOptions options;
             options.cruise_speed_mps = cruise_speed_mps;
             options.deceleration_mps2 = deceleration_mps2;
             return std::make_unique<CuspSequencer>(plan, controller, options);
           }),
           py::arg("plan"), py::arg("controller"), py::arg("cruise_speed_mps") = 1.5,
           py::arg("deceleration_mps2") = 0.5, py::keep_alive<1, 3>(),
           "cruise speed [m/s], braking [m/s^2]")
      .def(
          "speed_command",
          [](CuspSequencer& sequencer, const py::object& position, double period_s) {
            return sequencer.speed_command(to_vec2(position, "rear_axle_position"), period_s);
          },
          py::arg("rear_axle_position"), py::arg("period_s"),
          "Signed speed [m/s] for the coming period.")
      .def_property_readonly("active_piece", &CuspSequencer::active_piece)
      .def_property_readonly("finished", &CuspSequencer::finished);
}

}  // namespace smoothsteer::python
