//! Closest-point projection onto a Path: a pruned global scan and a warm-started local walk.
//! Both are noexcept and allocation-free so that controllers can call them every cycle.

#include <algorithm>
#include <cmath>
#include <limits>

#include "path_detail.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/path/path.hpp"

namespace smoothsteer {

PathProjection Path::project(Vec2 point) const noexcept {
  ProjectionHint unused;
  return project_global(point, unused);
}

PathProjection Path::project(Vec2 point, ProjectionHint& hint) const noexcept {
  return project(point, hint, ProjectionOptions{});
}

PathProjection Path::project(Vec2 point, ProjectionHint& hint,
                             const ProjectionOptions& options) const noexcept {
  const std::size_t count = segments_.size();
  if (count == 0) return {};
  if (hint.segment_index < count) {
    // Walk towards the side where the distance still decreases. Turning back means the local
    // minimum sits on the joint between the last two segments visited.
    std::size_t index = hint.segment_index;
    double warm = hint.parameter;
    int direction = 0;
    bool settled = false;
    SegmentProjection local;
    for (std::size_t step = 0; step < options.max_local_steps; ++step) {
      local = segments_[index].project_local(point, warm, /*exhaustive=*/false,
                                             options.compute_arc_length);
      const int wanted = local.clamped_at_end ? 1 : (local.clamped_at_start ? -1 : 0);
      if (wanted == 0 || wanted == -direction) {
        settled = true;
        break;
      }
      std::size_t next = index;
      if (wanted > 0) {
        next = index + 1 < count ? index + 1 : (closed_ ? 0 : index);
      } else {
        next = index > 0 ? index - 1 : (closed_ ? count - 1 : index);
      }
      if (next == index) {  // open path end (extension) or a single closed segment
        settled = true;
        break;
      }
      index = next;
      direction = wanted;
      warm = wanted > 0 ? 0.0 : segments_[index].parameter_end();
    }
    if (settled && local.distance_m <= options.global_search_distance_m) {
      return finish_projection(point, index, local, hint);
    }
  }
  return project_global(point, hint);
}

PathProjection Path::project_global(Vec2 point, ProjectionHint& hint) const noexcept {
  const std::size_t count = segments_.size();
  if (count == 0) return {};
  // Nearest-first without sorting (no allocation): the block, and inside it the segment, with
  // the smallest lower bound is projected first, so the pruning of all others starts tight.
  std::size_t best_index = ProjectionHint::none;
  SegmentProjection best;
  auto consider = [&](std::size_t i) {
    if (best_index != ProjectionHint::none &&
        norm(point - bounds_[i].center) - bounds_[i].radius > best.distance_m) {
      return;
    }
    const PathSegment& segment = segments_[i];
    const SegmentProjection local = segment.project_local(point, 0.5 * segment.parameter_end());
    if (best_index == ProjectionHint::none || local.distance_m < best.distance_m) {
      best = local;
      best_index = i;
    }
  };
  auto scan_block = [&](std::size_t b) {
    const std::size_t first = b * block_size;
    const std::size_t last = std::min(first + block_size, count);
    std::size_t nearest = first;
    double nearest_bound = std::numeric_limits<double>::infinity();
    for (std::size_t i = first; i < last; ++i) {
      const double lower_bound = norm(point - bounds_[i].center) - bounds_[i].radius;
      if (lower_bound < nearest_bound) {
        nearest_bound = lower_bound;
        nearest = i;
      }
    }
    consider(nearest);
    for (std::size_t i = first; i < last; ++i) {
      if (i != nearest) consider(i);
    }
  };
  auto block_lower_bound = [&](std::size_t b) {
    return norm(point - block_bounds_[b].center) - block_bounds_[b].radius;
  };
  std::size_t nearest_block = 0;
  for (std::size_t b = 1; b < block_bounds_.size(); ++b) {
    if (block_lower_bound(b) < block_lower_bound(nearest_block)) nearest_block = b;
  }
  scan_block(nearest_block);
  for (std::size_t b = 0; b < block_bounds_.size(); ++b) {
    if (b != nearest_block && block_lower_bound(b) <= best.distance_m) scan_block(b);
  }
  if (best_index == ProjectionHint::none) {  // only for a NaN query: keep the output defined
    best_index = 0;
    best = segments_.front().project_local(point, 0.0);
  }
  return finish_projection(point, best_index, best, hint);
}

PathProjection Path::finish_projection(Vec2 point, std::size_t index,
                                       const SegmentProjection& local,
                                       ProjectionHint& hint) const noexcept {
  hint.segment_index = index;
  hint.parameter = local.parameter;

  PathProjection result;
  result.segment_index = index;
  result.arc_length_m = segments_[index].s0 + local.local_arc_length_m;
  result.lateral_error_m = local.lateral_error_m;
  result.heading_rad = local.heading_rad;
  result.curvature = local.curvature;
  result.closest_point = local.point;

  const bool on_start_extension = !closed_ && index == 0 && local.clamped_at_start;
  const bool on_end_extension = !closed_ && index + 1 == segments_.size() && local.clamped_at_end;
  if (on_start_extension || on_end_extension) {
    // Open paths continue along their end tangents: project onto that half-line instead.
    const PathPoint& end = on_start_extension ? start_ : end_;
    const Vec2 tangent = unit_from_heading(end.heading_rad);
    const Vec2 offset = point - end.position;
    const double along = on_start_extension ? std::min(dot(offset, tangent), 0.0)
                                            : std::max(dot(offset, tangent), 0.0);
    result.arc_length_m = (on_start_extension ? 0.0 : length_) + along;
    result.closest_point = end.position + along * tangent;
    result.lateral_error_m = cross(tangent, offset);
    result.heading_rad = end.heading_rad;
    result.curvature = 0.0;
  } else if (closed_) {
    if (result.arc_length_m >= length_) result.arc_length_m -= length_;
    if (result.arc_length_m < 0.0) result.arc_length_m = 0.0;
  }
  return result;
}

}  // namespace smoothsteer
