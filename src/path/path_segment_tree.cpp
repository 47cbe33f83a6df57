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
#include <limits>

#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/path/path.hpp"

namespace smoothsteer {
namespace {

//! Distance from `point` to the box [lower, upper] (0 inside).
double box_distance(Vec2 point, Vec2 lower, Vec2 upper) noexcept {
  const double dx = std::max({lower.x - point.x, 0.0, point.x - upper.x});
  const double dy = std::max({lower.y - point.y, 0.0, point.y - upper.y});
  return std::sqrt(dx * dx + dy * dy);
}

}  // namespace

std::uint32_t Path::build_tree(std::uint32_t first, std::uint32_t count) {
  const auto index = static_cast<std::uint32_t>(tree_.size());
  tree_.push_back({});
  BoxNode node;
  node.first = first;
  node.count = count;
  if (count <= leaf_size) {
    const double inf = std::numeric_limits<double>::infinity();
    node.lower = {inf, inf};
    node.upper = {-inf, -inf};
    for (std::uint32_t i = first; i < first + count; ++i) {
      const PathSegment& segment = segments_[i];
      Vec2 lower = bounds_[i].center - Vec2{bounds_[i].radius, bounds_[i].radius};
      Vec2 upper = bounds_[i].center + Vec2{bounds_[i].radius, bounds_[i].radius};
      if (segment.kind == PathSegment::Kind::line) {  // exact: the box of the two end points
        const Vec2 end =
            segment.start + segment.length * unit_from_heading(segment.start_heading_rad);
        lower = {std::min(segment.start.x, end.x), std::min(segment.start.y, end.y)};
        upper = {std::max(segment.start.x, end.x), std::max(segment.start.y, end.y)};
      }
      node.lower = {std::min(node.lower.x, lower.x), std::min(node.lower.y, lower.y)};
      node.upper = {std::max(node.upper.x, upper.x), std::max(node.upper.y, upper.y)};
    }
  } else {
    const std::uint32_t half = count / 2;
    const std::uint32_t left = build_tree(first, half);
    node.right = build_tree(first + half, count - half);
    const BoxNode& a = tree_[left];
    const BoxNode& b = tree_[node.right];
    node.lower = {std::min(a.lower.x, b.lower.x), std::min(a.lower.y, b.lower.y)};
    node.upper = {std::max(a.upper.x, b.upper.x), std::max(a.upper.y, b.upper.y)};
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
    if (box_distance(point, node.lower, node.upper) > best_distance) continue;
    if (node.count <= leaf_size) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
        if (norm(point - bounds_[i].center) - bounds_[i].radius > best_distance) continue;
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
    const double left_distance = box_distance(point, tree_[left].lower, tree_[left].upper);
    const double right_distance =
        box_distance(point, tree_[node.right].lower, tree_[node.right].upper);
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
