#pragma once
//! \file path_plan.hpp
//! Paths with gear changes: a sequence of pieces, each driven forwards or in reverse, meeting at
//! cusps (parking manoeuvres, three-point turns). Each piece is its own open Path whose
//! direction is the direction of TRAVEL (for a reverse piece, the vehicle's heading plus pi), so
//! a projection onto the active piece can never land on the piece across a cusp.
//! Construction validates and throws std::invalid_argument naming the field and the rule.

#include <cstddef>
#include <memory>
#include <vector>

#include "smoothsteer/math/vec2.hpp"
#include "smoothsteer/path/path.hpp"

namespace smoothsteer {

enum class Gear { forward = 1, reverse = -1 };

//! +1 for forward, -1 for reverse: the sign of the speed on that piece.
constexpr double gear_sign(Gear gear) noexcept {
  return gear == Gear::forward ? 1.0 : -1.0;
}

struct PathPiece {
  std::shared_ptr<const Path> path;  //!< open, runs in the direction of travel
  Gear gear = Gear::forward;
};

class PathPlan {
 public:
  //! Distance within which one piece must start where the previous one ends [m].
  static constexpr double joint_tolerance_m = 1e-3;

  //! From pieces built elsewhere (PathBuilder, Path::from_waypoints, ...). Needs >= 1 piece,
  //! non-null open paths, each starting within joint_tolerance_m of the previous end.
  static PathPlan from_pieces(std::vector<PathPiece> pieces);
  //! Most gear changes of one plan: a parking manoeuvre has a handful, a shuttle route tens;
  //! each costs a stop and a rest (cusp_rest_s), so 10 000 is hours of manoeuvring. More are
  //! refused by from_pieces and by the scenario reader before it builds them.
  static constexpr std::size_t max_cusps = 10'000;
  //! From waypoints with a direction column: directions[i] (+1 forward, -1 reverse) is the gear
  //! on the way from waypoints[i] to waypoints[i + 1] (the last entry is not used). A change of
  //! sign makes waypoints[i] a cusp: one piece ends and the next starts there. Each piece is a
  //! C2 spline through its waypoints (Path::from_waypoints), so needs >= 2 of them.
  static PathPlan from_waypoints(const std::vector<Vec2>& waypoints,
                                 const std::vector<int>& directions);

  std::size_t piece_count() const noexcept { return pieces_.size(); }
  const PathPiece& piece(std::size_t index) const noexcept { return pieces_[index]; }
  //! Number of gear changes.
  std::size_t cusp_count() const noexcept;
  //! Vehicle pose at the end of the last piece: position and heading (travel heading, plus pi
  //! if the last piece is driven in reverse).
  Vec2 final_position() const noexcept;
  double final_vehicle_heading_rad() const noexcept;

 private:
  std::vector<PathPiece> pieces_;
};

}  // namespace smoothsteer
