#pragma once
//! \file smoothsteer.hpp
//! Umbrella header of the real-time core.

#include "smoothsteer/controller/controller_parameters.hpp"
#include "smoothsteer/controller/dubins_switching_law.hpp"
#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/controller/steering_controller.hpp"
#include "smoothsteer/controller/trailer_chain.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/math/pose2.hpp"
#include "smoothsteer/math/vec2.hpp"
#include "smoothsteer/path/path.hpp"
#include "smoothsteer/path/path_builder.hpp"
#include "smoothsteer/sim/kinematic_closed_loop.hpp"
#include "smoothsteer/sim/metrics.hpp"
#include "smoothsteer/sim/simulation.hpp"
#include "smoothsteer/sim/speed_profile.hpp"
#include "smoothsteer/status.hpp"
#include "smoothsteer/vehicle/kinematic_single_track.hpp"
#include "smoothsteer/vehicle/steering_actuator.hpp"
#include "smoothsteer/vehicle/vehicle_model.hpp"
#include "smoothsteer/vehicle/vehicle_parameters.hpp"
