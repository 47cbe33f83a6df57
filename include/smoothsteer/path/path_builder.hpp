#pragma once
//! \file path_builder.hpp
//! Builds G1-continuous paths of lines, arcs and clothoids piece by piece from a start pose,
//! like a turtle:
//!   Path p = PathBuilder({0, 0}, 0.0).line(10).clothoid(5, 0.2).arc(5, pi / 2)
//!                .clothoid(5, 0.0).line(10).build();
//! A clothoid starts at the curvature the previous piece ends with (0 before the first piece),
//! so its joints have no curvature jump.

#include <vector>

#include "smoothsteer/math/vec2.hpp"
#include "smoothsteer/path/path.hpp"
#include "smoothsteer/path/path_segment.hpp"

namespace smoothsteer {

class PathBuilder {
 public:
  //! Throws std::invalid_argument if the start pose is not finite.
  PathBuilder(Vec2 start, double heading_rad);

  //! Appends a straight piece. Throws unless `length_m` is finite and > 0.
  PathBuilder& line(double length_m);
  //! Appends an arc of radius `radius_m` turning by `angle_rad` (> 0 left, < 0 right). Throws
  //! unless the radius is finite and > 0 and the angle is finite and nonzero.
  PathBuilder& arc(double radius_m, double angle_rad);

  //! Appends a clothoid of length `length_m` whose curvature runs linearly from the current
  //! end curvature to `curvature_end` [1/m] (> 0 turning left). Throws unless the length is
  //! finite and > 0, the end curvature is finite and differs from the current one, and
  //! max(|curvature|) * length <= 4 pi.
  PathBuilder& clothoid(double length_m, double curvature_end);

  //! The path so far. With `closed`, the end must meet the start (see Path::from_segments).
  Path build(bool closed = false) const;

  //! End pose of the pieces so far (the start pose before the first piece).
  Vec2 end_position() const noexcept { return position_; }
  double end_heading_rad() const noexcept { return heading_rad_; }
  //! Curvature at the end of the pieces so far (0 before the first piece) [1/m].
  double end_curvature() const noexcept { return curvature_; }

 private:
  void append(const PathSegment& segment);

  std::vector<PathSegment> segments_;
  Vec2 position_;
  double heading_rad_ = 0.0;
  double curvature_ = 0.0;
};

}  // namespace smoothsteer
