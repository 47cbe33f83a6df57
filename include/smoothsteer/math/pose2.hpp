#pragma once
//! \file pose2.hpp
//! A planar pose: position and heading. Shared by the controller, the vehicle models and the
//! simulation, so it lives with the other math types rather than in vehicle/.

#include "smoothsteer/math/vec2.hpp"

namespace smoothsteer {

struct Pose2 {
  Vec2 position;             //!< reference point, e.g. the rear axle [m]
  double heading_rad = 0.0;  //!< psi [rad]
};

}  // namespace smoothsteer
