#pragma once
//! \file path.hpp
//! Reference paths: straight lines, sequences of lines, arcs and clothoids, circles and C2
//! cubic splines through waypoints, with warm-started closest-point projection.
//!
//! Conventions
//!  - Arc length s [m] starts at 0 at the first point.
//!  - The lateral error e [m] is signed: positive when the point is LEFT of the path direction
//!    (paper Fig. `problem`: e > 0 above a path that runs in +x).
//!  - Open paths extend along the end tangents: s < 0 and s > length() are valid projections
//!    onto those half-lines, with zero curvature there.
//!  - Closed paths (circles, closed line/arc loops) wrap s into [0, length()).
//! Construction validates its input and throws std::invalid_argument with a message that names
//! the field, the value and the rule. Evaluation and projection are noexcept and never allocate.

#include <cstddef>
#include <cstdint>
#include <numbers>
#include <optional>
#include <span>
#include <vector>

#include "smoothsteer/math/vec2.hpp"
#include "smoothsteer/path/path_segment.hpp"

namespace smoothsteer {

//! A point on the path.
struct PathPoint {
  Vec2 position;             //!< [m]
  double heading_rad = 0.0;  //!< tangent direction [rad]
  double curvature = 0.0;    //!< [1/m], positive = turning left
};

//! Result of a closest-point projection.
struct PathProjection {
  double arc_length_m = 0.0;      //!< s of the closest point (outside [0, L] on end extensions)
  double lateral_error_m = 0.0;   //!< signed distance, left positive
  double heading_rad = 0.0;       //!< path tangent at the closest point
  double curvature = 0.0;         //!< path curvature at the closest point [1/m]
  Vec2 closest_point;             //!< [m]
  std::size_t segment_index = 0;  //!< segment that holds the closest point
};

//! Warm-start memory of one projecting point (e.g. the lead wheel). Owned by the caller so that
//! one const Path can be shared by many controllers and threads.
struct ProjectionHint {
  static constexpr std::size_t none = static_cast<std::size_t>(-1);
  std::size_t segment_index = none;  //!< segment of the previous projection, or none
  double parameter = 0.0;            //!< segment-local parameter of the previous projection
  void reset() noexcept { segment_index = none; }
};

//! How Path::from_waypoints fits waypoints that carry noise (a planner's samples, a recording).
struct WaypointSmoothing {
  //! RMS distance of the fitted path from the waypoints at their knots [m] (Reinsch's
  //! criterion): the smoothest C2 cubic spline that stays this close. 0 interpolates exactly.
  //! For Gaussian jitter of standard deviation sigma on each coordinate, sigma sqrt(2) is the
  //! jitter's own RMS distance. Larger than the least-squares line's residual gives that line.
  double tolerance_m = 0.0;
  //! Fit at least the jitter the waypoints show: the tolerance is then the larger of
  //! tolerance_m and sqrt(2) estimate_waypoint_jitter(waypoints) (path/waypoint_jitter.hpp),
  //! so that a stack need not know its planner's noise. Clean waypoints estimate 0 and are
  //! interpolated exactly (with tolerance_m 0).
  bool estimate_jitter = false;
  //! Restore the corners the fit cuts: where the fit bends tighter than a 50 m radius and the
  //! tolerance is at least that of 1 cm of jitter (0.014 m), the fit of its own residual at the
  //! same smoothing weight is added (twicing, Tukey 1977), which cancels the smoothing's
  //! first-order bias. The knots are then closer to the waypoints than the tolerance. A planner's
  //! windows with 2-5 cm of jitter through tight corners: the car's system ran 0.06-0.08 instead
  //! of 0.10-0.15 m (docs/controller.md, "Paths as they come"). false: Reinsch's fit alone.
  bool restore_corners = true;
};

class Path {
 public:
  //! Options for the projection search.
  struct ProjectionOptions {
    //! Beyond this distance from the path the warm start is not trusted and a global search is
    //! run (far from the path, the globally closest branch is the right one to approach).
    double global_search_distance_m = 5.0;
    //! The warm-started local walk visits at most this many segments before falling back to a
    //! global search.
    std::size_t max_local_steps = 64;
    //! false skips the arc length of the closest point (arc_length_m is then only meaningful
    //! on lines and arcs); saves the quadrature on splines when only e, heading and curvature
    //! are needed, as for the controller's lead wheel.
    bool compute_arc_length = true;
    //! The hint of another point projected close to this one in the same cycle (another wheel
    //! of the same vehicle), or null. When the search turns global, the distance to its segment
    //! bounds the search from the start: far from the path a cycle then descends the tree cold
    //! once, not once per point. The result stays the global closest point.
    const ProjectionHint* nearby = nullptr;
  };

  //! Largest |coordinate| and radius of a path [m] (ControllerInputRange::max_abs_coordinate_m);
  //! beyond it squares and products inside the projection overflow. Lengths may reach
  //! max_length_m (a circle of radius max_extent_m), arcs need |curvature| >= 1 / max_extent_m.
  static constexpr double max_extent_m = 1e9;
  static constexpr double max_length_m = 1e10;

  //! An infinite-looking straight line: from `start` along `heading_rad`, `length_m` long, with
  //! both ends extended along the tangent.
  static Path straight_line(Vec2 start, double heading_rad, double length_m = 100.0);
  //! A full circle, closed. `counter_clockwise` = true turns left (positive curvature).
  //! Starts at the point of the circle at angle `start_angle_rad` around the center.
  static Path circle(Vec2 center, double radius_m, bool counter_clockwise = true,
                     double start_angle_rad = 0.0);
  //! A C2 natural cubic spline through the waypoints, chord-length parametrized. Heading and
  //! curvature are continuous. Needs >= 2 points; consecutive duplicates and a turn sharper
  //! than max_waypoint_turn_rad (find_reversal) are rejected by index.
  static Path from_waypoints(const std::vector<Vec2>& waypoints);
  //! A C2 smoothing cubic spline near the waypoints (src/path/smoothing_spline.cpp): its
  //! curvature and curvature rate come from the fit, not from the noise between the points.
  //! Same checks as the interpolating overload, plus a finite tolerance in [0, 1e9] m; refused
  //! by index if the fitted path doubles back. Set-up time only: O(n) per bisection step.
  static Path from_waypoints(const std::vector<Vec2>& waypoints, WaypointSmoothing smoothing);
  //! Sharpest turn from one chord of from_waypoints to the next [rad]. A sharper one doubles
  //! back: the spline runs into a cusp (0 -> 30 -> 0 on one line) where no forward path goes;
  //! a change of direction is a PathPlan with one piece per gear (docs/cusps.md).
  static constexpr double max_waypoint_turn_rad = 2.0 * std::numbers::pi / 3.0;
  //! Turns of the chords closer together than this count as one turn [m]: two turns of 90
  //! degrees 1 um apart double back as one of 180 degrees does. No vehicle turns by
  //! max_waypoint_turn_rad within 1 mm (a radius below 0.5 mm).
  static constexpr double max_waypoint_turn_spread_m = 1e-3;
  //! Index of the first waypoint from which the chords turn by more than max_waypoint_turn_rad
  //! in total, at it or together with the turns at the waypoints less than
  //! max_waypoint_turn_spread_m after it (from_waypoints refuses it), or none. Readers use it to
  //! name the row of a file. Linear in the number of waypoints.
  static std::optional<std::size_t> find_reversal(const std::vector<Vec2>& waypoints);
  //! Builds from explicit segments (see PathBuilder); checks G1 continuity between consecutive
  //! segments (and end -> start if closed) within 1e-6 m and 1e-6 rad. The `s0` fields are
  //! recomputed; a cubic's `length` must match its coefficients.
  static Path from_segments(std::vector<PathSegment> segments, bool closed = false);

  double length() const noexcept { return length_; }
  bool is_closed() const noexcept { return closed_; }
  std::size_t segment_count() const noexcept { return segments_.size(); }
  const std::vector<PathSegment>& segments() const noexcept { return segments_; }
  //! Largest |curvature| along the path [1/m].
  double max_abs_curvature() const noexcept { return max_abs_curvature_; }

  //! Curvature sampled every curvature_sample_spacing_m() from s = 0 to length(), built once
  //! with the path, for the feedforward's preview (docs/feedforward.md): a look-up, no search.
  double curvature_sample_spacing_m() const noexcept { return curvature_spacing_; }
  //! The sample nearest to arc length s (wrapped if closed; 0 on the straight end extensions).
  double sampled_curvature(double arc_length_m) const noexcept;
  //! Sample i (wrapped if closed; 0 outside [0, length()] on open paths). Inline for the
  //! previews' loops: an index inside the samples is a plain read (on a closed path the last
  //! sample, at s = length(), is the first one's value), the rest goes out of line.
  double curvature_sample(long index) const noexcept {
    if (index >= 0 && index < static_cast<long>(curvature_samples_.size())) {
      return curvature_samples_[static_cast<std::size_t>(index)];
    }
    return curvature_sample_outside(index);
  }
  //! All samples, sample i at s = i curvature_sample_spacing_m() (read-only).
  std::span<const double> curvature_samples() const noexcept { return curvature_samples_; }
  //! A step of the curvature where two segments meet, or at an end of an open path against its
  //! straight extension (docs/feedforward.md, section 2b: the planned jumps).
  struct CurvatureJump {
    double arc_length_m = 0.0;  //!< where the step is [m]
    double before = 0.0;        //!< curvature just before it [1/m]
    double after = 0.0;         //!< curvature just after it [1/m]
  };
  //! Steps smaller than this are joints of a smooth path, not jumps [1/m].
  static constexpr double min_curvature_jump = 1e-6;
  //! The path's curvature steps, sorted by arc length, built once with the path (a closed
  //! path's joint at s = 0 is listed there).
  const std::vector<CurvatureJump>& curvature_jumps() const noexcept { return curvature_jumps_; }
  //! A step of the curvature's slope where a line, an arc or a clothoid meets another (a
  //! clothoid's start or end), or an open path's end against its straight extension
  //! (docs/feedforward.md, section 2b: the planned kinks). Joints of cubic spline pieces are
  //! not listed: their slope steps are those of a smooth curve.
  struct CurvatureKink {
    double arc_length_m = 0.0;  //!< where the step is [m]
    double before = 0.0;        //!< d curvature / ds just before it [1/m^2]
    double after = 0.0;         //!< d curvature / ds just after it [1/m^2]
  };
  //! Slope steps smaller than this are not kinks [1/m^2].
  static constexpr double min_curvature_kink = 1e-7;
  //! The path's kinks, sorted by arc length, built once with the path.
  const std::vector<CurvatureKink>& curvature_kinks() const noexcept { return curvature_kinks_; }
  //! The largest |after - before| of curvature_kinks() [1/m^2], 0 without kinks.
  double max_abs_curvature_kink() const noexcept { return max_abs_curvature_kink_; }
  //! A spline through waypoints spreads a clothoid's start (a kink) over a knot or two, where
  //! no kink is listed. On a path with cubic pieces: the largest change of the sampled
  //! curvature's slope across spline_kink_spread_m [1/m^2] (a kink's step, once spread), the
  //! curvature taken as its mean over one knot spacing (the spline's ringing after a kink
  //! cancels there); 0 on a path of lines, arcs and clothoids, whose kinks are listed.
  double max_abs_spline_kink() const noexcept { return max_abs_spline_kink_; }
  //! The distance over which max_abs_spline_kink() measures a slope's change [m].
  static constexpr double spline_kink_spread_m = 2.0;
  //! An open path's first and last metres that max_abs_spline_kink() leaves out [m].
  static constexpr double spline_end_margin_m = 5.0;

  //! Position, heading and curvature at arc length s (wrapped if closed, extended if open).
  PathPoint evaluate(double arc_length_m) const noexcept;

  //! Global closest-point projection (no warm start), including the end extensions of open
  //! paths: O(log N) on typical paths through a bounding-box hierarchy over the segments.
  PathProjection project(Vec2 point) const noexcept;
  //! Warm-started projection: amortised O(1) while the point moves continuously; falls back to
  //! the global search on the first call, after `hint.reset()`, after too many local steps, or
  //! when the point is farther than `options.global_search_distance_m` from the path.
  PathProjection project(Vec2 point, ProjectionHint& hint) const noexcept;
  PathProjection project(Vec2 point, ProjectionHint& hint,
                         const ProjectionOptions& options) const noexcept;

  //! For replanning: a hint on this path at the point nearest to where `hint` pointed on
  //! `previous` (a global projection, O(log N), allocation free). An empty hint stays empty.
  ProjectionHint reseed_hint(const Path& previous, const ProjectionHint& hint) const noexcept;

 private:
  //! Node of the bounding-volume hierarchy over consecutive segments [first, first + count):
  //! an axis-aligned box. Nodes are stored depth first: the left child follows its parent, the
  //! right child sits at `right`. Leaves hold at most leaf_size segments.
  struct BoxNode {
    SegmentBox box;
    std::uint32_t first = 0;
    std::uint32_t count = 0;
    std::uint32_t right = 0;
  };
  static constexpr std::uint32_t leaf_size = 4;
  //! Depth-first stack of the query; the tree halves index ranges, so its depth is about
  //! log2(N / leaf_size) and this holds paths far beyond 2^60 segments.
  static constexpr std::size_t max_stack = 128;

  //! Sets arc lengths, bounds and cached end poses; the segments are already validated.
  static Path assemble(std::vector<PathSegment> segments, bool closed);
  //! Builds tree_ over segments [first, first + count), whose boxes are `boxes`, and returns
  //! the node's index.
  std::uint32_t build_tree(const std::vector<SegmentBox>& boxes, std::uint32_t first,
                           std::uint32_t count);
  //! A point on the path and its segment: an upper bound that the global search starts from.
  struct SearchSeed {
    std::size_t segment_index = ProjectionHint::none;
    SegmentProjection local;
  };
  PathProjection project_global(Vec2 point, ProjectionHint& hint,
                                const SearchSeed& seed) const noexcept;
  //! The nearer of `seed` and the warm projection from `hint` onto its segment.
  SearchSeed nearer_seed(Vec2 point, const SearchSeed& seed,
                         const ProjectionHint* hint) const noexcept;
  //! curvature_sample() for an index outside the samples: wrapped if closed, else 0.
  double curvature_sample_outside(long index) const noexcept;
  //! Distance from `point` to the start (start = true) or end extension half-line of an open
  //! path, or infinity if its closest point is not strictly on the half-line.
  double extension_distance(Vec2 point, bool start) const noexcept;
  //! Replaces `local`, a result on the first (start = true) or last segment, by the extension
  //! beyond that end if the extension is nearer or `local` is clamped at that end (returns
  //! true then).
  bool adopt_extension(Vec2 point, bool start, SegmentProjection& local) const noexcept;
  //! Turns a segment-local result into a path result (s, end extensions, wrap) and stores
  //! the warm start.
  PathProjection finish_projection(Vec2 point, std::size_t index, const SegmentProjection& local,
                                   ProjectionHint& hint) const noexcept;

  std::vector<PathSegment> segments_;
  std::vector<SegmentCapsule> capsules_;  //!< one per segment, contains it
  std::vector<BoxNode> tree_;
  PathPoint start_;  //!< pose at s = 0, for the start extension
  PathPoint end_;    //!< pose at s = length(), for the end extension
  double length_ = 0.0;
  double max_abs_curvature_ = 0.0;
  bool closed_ = false;
  static constexpr double curvature_sample_spacing = 0.5;         //!< [m]
  static constexpr std::size_t max_curvature_samples = 1u << 22;  //!< 32 MiB at most
  double curvature_spacing_ = curvature_sample_spacing;
  std::vector<double> curvature_samples_;
  std::vector<CurvatureJump> curvature_jumps_;
  std::vector<CurvatureKink> curvature_kinks_;
  double max_abs_curvature_kink_ = 0.0;
  double max_abs_spline_kink_ = 0.0;
  //! max_abs_spline_kink() of the samples `spacing` apart, from knots `knot_spacing` apart.
  static double spline_kink(const std::vector<double>& samples, double spacing, double knot_spacing,
                            bool closed) noexcept;
};

}  // namespace smoothsteer
