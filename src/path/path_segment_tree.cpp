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

//! Distance from `point` to `box` (0 inside).
double box_distance(Vec2 point, const SegmentBox& box) noexcept {
  const double dx = std::max({box.lower.x - point.x, 0.0, point.x - box.upper.x});
  const double dy = std::max({box.lower.y - point.y, 0.0, point.y - box.upper.y});
  return std::sqrt(dx * dx + dy * dy);
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
  // Bezier control points of p(t) = a0 + a1 t + a2 t^2 + a3 t^3 on [0, T]; the curve lies in
  // their convex hull.
  const auto& x = segment.x_coefficients;
  const auto& y = segment.y_coefficients;
  const double t = segment.t_end;
  const Vec2 b0{x[0], y[0]};
  const Vec2 b1 = b0 + (t / 3.0) * Vec2{x[1], y[1]};
  const Vec2 b2 = b1 + (t / 3.0) * Vec2{x[1], y[1]} + (t * t / 3.0) * Vec2{x[2], y[2]};
  const Vec2 b3 =
      b0 + t * Vec2{x[1], y[1]} + t * t * Vec2{x[2], y[2]} + t * t * t * Vec2{x[3], y[3]};
  const SegmentBox hull = box_of_points({b0, b1, b2, b3});
  return {{std::max(box.lower.x, hull.lower.x), std::max(box.lower.y, hull.lower.y)},
          {std::min(box.upper.x, hull.upper.x), std::min(box.upper.y, hull.upper.y)}};
}

std::uint32_t Path::build_tree(std::uint32_t first, std::uint32_t count) {
  const auto index = static_cast<std::uint32_t>(tree_.size());
  tree_.push_back({});
  BoxNode node;
  node.first = first;
  node.count = count;
  if (count <= leaf_size) {
    node.box = boxes_[first];
    for (std::uint32_t i = first + 1; i < first + count; ++i) node.box = merge(node.box, boxes_[i]);
  } else {
    const std::uint32_t half = count / 2;
    const std::uint32_t left = build_tree(first, half);
    node.right = build_tree(first + half, count - half);
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

PathProjection Path::project_global(Vec2 point, ProjectionHint& hint) const noexcept {
  const std::size_t count = segments_.size();
  if (count == 0) return {};

  // The end extensions first: their distance is exact and cheap, and prunes the tree.
  const double to_start = extension_distance(point, /*start=*/true);
  const double to_end = extension_distance(point, /*start=*/false);
  double best_distance = std::min(to_start, to_end);
  std::size_t best_index = ProjectionHint::none;
  SegmentProjection best;

  std::array<std::uint32_t, max_stack> stack;
  std::size_t depth = 0;
  stack[depth++] = 0;
  while (depth > 0) {
    const std::uint32_t node_index = stack[--depth];
    const BoxNode& node = tree_[node_index];
    if (box_distance(point, node.box) > best_distance) continue;
    if (node.count <= leaf_size) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
        if (box_distance(point, boxes_[i]) > best_distance) continue;
        const PathSegment& segment = segments_[i];
        const SegmentProjection local = segment.project_local(point, 0.5 * segment.parameter_end());
        if (local.distance_m < best_distance) {
          best_distance = local.distance_m;
          best = local;
          best_index = i;
        }
      }
      continue;
    }
    const std::uint32_t left = node_index + 1;  // depth-first layout
    const double left_distance = box_distance(point, tree_[left].box);
    const double right_distance = box_distance(point, tree_[node.right].box);
    // Push the farther child first so that the nearer one is searched first.
    const bool left_first = left_distance <= right_distance;
    const std::uint32_t near_child = left_first ? left : node.right;
    const std::uint32_t far_child = left_first ? node.right : left;
    if (std::max(left_distance, right_distance) <= best_distance && depth < max_stack) {
      stack[depth++] = far_child;
    }
    if (std::min(left_distance, right_distance) <= best_distance && depth < max_stack) {
      stack[depth++] = near_child;
    }
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
