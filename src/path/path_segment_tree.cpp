//! The global closest-point search: a bounding-volume hierarchy (BVH) of axis-aligned boxes over
//! consecutive segments, searched depth first with the nearer child first and pruned by the
//! box distance, plus the two end extensions of open paths. Built once with the path; queries
//! are noexcept and allocation free (a fixed-size stack).
//!
//! Consecutive segments of a continuous path lie next to each other, so halving the index range
//! gives tight boxes without sorting. Far from the path, the nearest boxes are visited first and
//! the first leaves give a distance that prunes almost every other subtree: O(log N) nodes on
//! typical paths. (A query equidistant from every segment, the center of a circle made of many
//! segments, still visits all of them; every exact search must.)

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <limits>

#include "path_detail.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/path/path.hpp"

namespace smoothsteer {
namespace {

//! Squared distance from `point` to `box` (0 inside).
double box_distance_squared(Vec2 point, const SegmentBox& box) noexcept {
  const double dx = std::max({box.lower.x - point.x, 0.0, point.x - box.upper.x});
  const double dy = std::max({box.lower.y - point.y, 0.0, point.y - box.upper.y});
  return dx * dx + dy * dy;
}

double distance_to_chord(Vec2 point, Vec2 from, Vec2 to) noexcept {
  const Vec2 chord = to - from;
  const double length_squared = dot(chord, chord);
  const double along =
      length_squared > 0.0 ? std::clamp(dot(point - from, chord) / length_squared, 0.0, 1.0) : 0.0;
  return norm(point - (from + along * chord));
}

//! Bezier control points of a cubic segment p(t) = a0 + a1 t + a2 t^2 + a3 t^3 on [0, T]: the
//! curve lies in their convex hull.
std::array<Vec2, 4> bezier_control_points(const PathSegment& segment) noexcept {
  const auto& x = segment.x_coefficients;
  const auto& y = segment.y_coefficients;
  const double t = segment.t_end;
  const Vec2 b0{x[0], y[0]};
  const Vec2 b1 = b0 + (t / 3.0) * Vec2{x[1], y[1]};
  const Vec2 b2 = b1 + (t / 3.0) * Vec2{x[1], y[1]} + (t * t / 3.0) * Vec2{x[2], y[2]};
  const Vec2 b3 =
      b0 + t * Vec2{x[1], y[1]} + t * t * Vec2{x[2], y[2]} + t * t * t * Vec2{x[3], y[3]};
  return {b0, b1, b2, b3};
}

//! A lower bound of the distance from `point` to the segment inside `capsule`.
double capsule_distance(Vec2 point, const SegmentCapsule& capsule) noexcept {
  return distance_to_chord(point, capsule.from, capsule.to) - capsule.radius;
}

SegmentBox merge(const SegmentBox& a, const SegmentBox& b) noexcept {
  return {{std::min(a.lower.x, b.lower.x), std::min(a.lower.y, b.lower.y)},
          {std::max(a.upper.x, b.upper.x), std::max(a.upper.y, b.upper.y)}};
}

SegmentBox box_of_points(std::initializer_list<Vec2> points) noexcept {
  const double inf = std::numeric_limits<double>::infinity();
  SegmentBox box{{inf, inf}, {-inf, -inf}};
  for (const Vec2& p : points) box = merge(box, {p, p});
  return box;
}

}  // namespace

SegmentBox detail::tighten_box(const PathSegment& segment, const SegmentBox& box) noexcept {
  if (segment.kind == PathSegment::Kind::line) {
    return box_of_points(
        {segment.start,
         segment.start + segment.length * unit_from_heading(segment.start_heading_rad)});
  }
  if (segment.kind != PathSegment::Kind::cubic) return box;
  const std::array<Vec2, 4> b = bezier_control_points(segment);  // the curve lies in their hull
  const SegmentBox hull = box_of_points({b[0], b[1], b[2], b[3]});
  return {{std::max(box.lower.x, hull.lower.x), std::max(box.lower.y, hull.lower.y)},
          {std::min(box.upper.x, hull.upper.x), std::min(box.upper.y, hull.upper.y)}};
}

SegmentCapsule detail::segment_capsule(const PathSegment& segment) noexcept {
  const Vec2 start = segment.evaluate_parameter(0.0).position;
  const Vec2 end = segment.evaluate_parameter(segment.parameter_end()).position;
  if (segment.kind == PathSegment::Kind::line) return {start, end, 0.0};
  if (segment.kind == PathSegment::Kind::clothoid) {
    // Half the minor axis of the ellipse sqrt((L/2)^2 - (c/2)^2), factored against
    // cancellation, plus a rounding margin.
    const double chord = norm(end - start);
    const double gap = std::max(segment.length - chord, 0.0);
    return {start, end,
            0.5 * std::sqrt(gap * (segment.length + chord)) + 1e-9 + 1e-12 * segment.length};
  }
  if (segment.kind == PathSegment::Kind::arc) {
    const double radius = 1.0 / std::abs(segment.curvature);
    const double sweep = std::abs(segment.curvature) * segment.length;
    if (sweep <= pi) return {start, end, radius * (1.0 - std::cos(0.5 * sweep))};
    const Vec2 forward = unit_from_heading(segment.start_heading_rad);
    const Vec2 center = segment.start + (1.0 / segment.curvature) * Vec2{-forward.y, forward.x};
    return {center, center, radius};
  }
  const auto [b0, b1, b2, b3] = bezier_control_points(segment);
  // The distance to the chord is convex, so its maximum over the control points' hull (which
  // holds the curve) sits at a control point. Rounding margin: 1e-9 m.
  const double deviation =
      std::max(distance_to_chord(b1, b0, b3), distance_to_chord(b2, b0, b3)) + 1e-9;
  return {b0, b3, deviation};
}

std::uint32_t Path::build_tree(const std::vector<SegmentBox>& boxes, std::uint32_t first,
                               std::uint32_t count) {
  const auto index = static_cast<std::uint32_t>(tree_.size());
  tree_.push_back({});
  BoxNode node;
  node.first = first;
  node.count = count;
  if (count <= leaf_size) {
    node.box = boxes[first];
    for (std::uint32_t i = first + 1; i < first + count; ++i) node.box = merge(node.box, boxes[i]);
  } else {
    const std::uint32_t half = count / 2;
    const std::uint32_t left = build_tree(boxes, first, half);
    node.right = build_tree(boxes, first + half, count - half);
    node.box = merge(tree_[left].box, tree_[node.right].box);
  }
  tree_[index] = node;
  return index;
}

double Path::extension_distance(Vec2 point, bool start) const noexcept {
  if (closed_) return std::numeric_limits<double>::infinity();
  const PathPoint& end = start ? start_ : end_;
  const Vec2 tangent = unit_from_heading(end.heading_rad);
  const Vec2 offset = point - end.position;
  const double along = dot(offset, tangent);
  if (start ? !(along < 0.0) : !(along > 0.0)) return std::numeric_limits<double>::infinity();
  return std::abs(cross(tangent, offset));
}

PathProjection Path::project_global(Vec2 point, ProjectionHint& hint,
                                    const SearchSeed& seed) const noexcept {
  const std::size_t count = segments_.size();
  if (count == 0) return {};

  // The end extensions first: their distance is exact and cheap, and prunes the tree.
  const double to_start = extension_distance(point, /*start=*/true);
  const double to_end = extension_distance(point, /*start=*/false);
  double best_distance = std::min(to_start, to_end);
  std::size_t best_index = ProjectionHint::none;
  SegmentProjection best;
  // A seed (a point of the path near the query, from a warm start) bounds the search from the
  // start: only boxes nearer than it are opened. Any point of the path is a valid bound.
  if (seed.segment_index < count && seed.local.distance_m < best_distance) {
    best_distance = seed.local.distance_m;
    best = seed.local;
    best_index = seed.segment_index;
  }

  auto consider = [&](std::uint32_t i) {
    const PathSegment& segment = segments_[i];
    const SegmentProjection local =
        segment.project_local(point, 0.5 * segment.parameter_end(), /*exhaustive=*/true,
                              /*with_arc_length=*/false);
    if (local.distance_m < best_distance) {
      best_distance = local.distance_m;
      best = local;
      best_index = i;
    }
  };
  auto segment_bound_squared = [&](std::uint32_t i) {
    const double bound = std::max(capsule_distance(point, capsules_[i]), 0.0);
    return bound * bound;
  };
  // Depth first, nearer child first, pruned by the box and capsule lower bounds. (A best-first
  // priority queue visits slightly fewer nodes but cost 1.8x more per query here.)
  auto depth_first = [&](std::uint32_t root) {
    std::array<std::uint32_t, max_stack> stack;
    std::size_t depth = 0;
    stack[depth++] = root;
    while (depth > 0) {
      const BoxNode& node = tree_[stack[--depth]];
      if (box_distance_squared(point, node.box) > best_distance * best_distance) continue;
      if (node.count <= leaf_size) {
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
          if (segment_bound_squared(i) <= best_distance * best_distance) consider(i);
        }
        continue;
      }
      const std::uint32_t left = static_cast<std::uint32_t>(&node - tree_.data()) + 1;
      const bool left_nearer = box_distance_squared(point, tree_[left].box) <=
                               box_distance_squared(point, tree_[node.right].box);
      if (depth + 2 > max_stack) continue;  // unreachable: the depth is ~log2(N)
      stack[depth++] = left_nearer ? node.right : left;
      stack[depth++] = left_nearer ? left : node.right;
    }
  };

  depth_first(0);
  if (best_index != ProjectionHint::none) {  // the arc length only for the winner
    best.local_arc_length_m = segments_[best_index].arc_length_at(best.parameter);
  }

  if (best_index == ProjectionHint::none) {
    const double inf = std::numeric_limits<double>::infinity();
    if (to_start < inf || to_end < inf) {
      // An end extension is nearest: finish_projection projects a clamped end onto it.
      const bool start_wins = to_start <= to_end;
      best_index = start_wins ? 0 : count - 1;
      best.parameter = start_wins ? 0.0 : segments_[best_index].parameter_end();
      best.clamped_at_start = start_wins;
      best.clamped_at_end = !start_wins;
    } else {  // only for a NaN query: keep the output defined
      best_index = 0;
      best = segments_.front().project_local(point, 0.0);
    }
  }
  return finish_projection(point, best_index, best, hint);
}

}  // namespace smoothsteer
