#pragma once
//! \file path_builder.hpp
//! Builds G1-continuous line/arc paths piece by piece from a start pose, like a turtle:
//!   Path p = PathBuilder({0, 0}, 0.0).line(10).arc(5, pi / 2).line(10).build();

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

  //! The path so far. With `closed`, the end must meet the start (see Path::from_segments).
  Path build(bool closed = false) const;

  //! End pose of the pieces so far (the start pose before the first piece).
  Vec2 end_position() const noexcept { return position_; }
  double end_heading_rad() const noexcept { return heading_rad_; }

 private:
  void append(const PathSegment& segment);

  std::vector<PathSegment> segments_;
  Vec2 position_;
  double heading_rad_ = 0.0;
};

}  // namespace smoothsteer
