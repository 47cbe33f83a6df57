//! Closest-point projection onto a Path: the warm-started local walk and the conversion of a
//! segment result into a path result (the global search is in path_segment_tree.cpp).
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
  return project_global(point, unused, SearchSeed{});
}

PathProjection Path::project(Vec2 point, ProjectionHint& hint) const noexcept {
  return project(point, hint, ProjectionOptions{});
}

PathProjection Path::project(Vec2 point, ProjectionHint& hint,
                             const ProjectionOptions& options) const noexcept {
  const std::size_t count = segments_.size();
  if (count == 0) return {};
  SearchSeed seed;
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
      // On an open path the extensions are the neighbours of the end segments (path.hpp): one
      // that is nearer than the local result ends the walk there.
      if (index == 0 && adopt_extension(point, /*start=*/true, local)) {
        settled = true;
        break;
      }
      if (index + 1 == count && adopt_extension(point, /*start=*/false, local)) {
        settled = true;
        break;
      }
      // Farther than the trusted distance from the hint's segment: the point jumped or left the
      // path, and the global search (O(log N)) is cheaper than a long walk.
      if (step == 0 && !(local.distance_m <= options.global_search_distance_m)) {
        seed = {index, local};
        break;
      }
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
  return project_global(point, hint, nearer_seed(point, seed, options.nearby));
}

Path::SearchSeed Path::nearer_seed(Vec2 point, const SearchSeed& seed,
                                   const ProjectionHint* hint) const noexcept {
  if (hint == nullptr || hint->segment_index >= segments_.size()) return seed;
  const SegmentProjection local = segments_[hint->segment_index].project_local(
      point, hint->parameter, /*exhaustive=*/false, /*with_arc_length=*/false);
  if (seed.segment_index < segments_.size() && !(local.distance_m < seed.local.distance_m)) {
    return seed;
  }
  return {hint->segment_index, local};
}

ProjectionHint Path::reseed_hint(const Path& previous, const ProjectionHint& hint) const noexcept {
  ProjectionHint seeded;
  if (hint.segment_index >= previous.segments_.size() || segments_.empty()) return seeded;
  const Vec2 where =
      previous.segments_[hint.segment_index].evaluate_parameter(hint.parameter).position;
  project_global(where, seeded, SearchSeed{});
  return seeded;
}

bool Path::adopt_extension(Vec2 point, bool start, SegmentProjection& local) const noexcept {
  if (closed_) return false;
  const double distance = extension_distance(point, start);
  if (!(distance < local.distance_m) && !(start ? local.clamped_at_start : local.clamped_at_end)) {
    return false;
  }
  const std::size_t index = start ? 0 : segments_.size() - 1;
  local.distance_m = std::min(distance, local.distance_m);
  local.parameter = start ? 0.0 : segments_[index].parameter_end();
  local.clamped_at_start = start;
  local.clamped_at_end = !start;
  return true;
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
