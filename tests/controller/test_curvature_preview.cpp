// The rate-limited curvature preview (feedforward.hpp, preview_curvature; docs/feedforward.md
// section 2): at each of its three points it is the midpoint of the path's sampled curvature's
// upper and lower envelopes of slope 2 L_ff, clamped to the bound. The test writes that
// definition out per point, over a window wider than the preview's reach, with the path's own
// sample look-up (wrapped on closed paths, 0 on the straight extensions of open ones), and
// requires the same value to the last bit: the preview reads the samples directly where its
// window lies inside the path and must not change the arithmetic.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "smoothsteer/controller/feedforward.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/path/path_builder.hpp"
#include "support/property.hpp"

namespace smoothsteer {
namespace {

using namespace smoothsteer::testing;

//! Lines, arcs and clothoids of random length and curvature; when `closed`, a stadium (two
//! lines, two half circles: four curvature jumps, one of them where the path closes).
Path random_piecewise_path(Random& random, bool closed, double bound) {
  if (closed) {
    const double straight = random.uniform(5.0, 40.0);
    const double radius = 1.0 / (bound * random.uniform(0.5, 1.5));
    return PathBuilder({0.0, 0.0}, 0.0)
        .line(straight)
        .arc(radius, pi)
        .line(straight)
        .arc(radius, pi)
        .build(true);
  }
  PathBuilder builder({0.0, 0.0}, random.uniform(-pi, pi));
  builder.line(random.uniform(2.0, 20.0));
  const int pieces = random.integer(2, 6);
  for (int i = 0; i < pieces; ++i) {
    // Up to 1.5 times the bound, so that the clamped jumps reach 2 bound.
    const double curvature = (random.coin() ? 1.0 : -1.0) * bound * random.uniform(0.1, 1.5);
    if (random.coin()) {
      builder.arc(1.0 / std::abs(curvature),
                  (curvature > 0.0 ? 1.0 : -1.0) * random.uniform(0.2, 1.2));
    } else {
      builder.clothoid(random.uniform(2.0, 15.0), curvature);
    }
  }
  builder.line(random.uniform(2.0, 20.0));
  return builder.build();
}

//! The definition at one point: index `point` of the samples, slope `slope` per sample.
double envelope_midpoint(const Path& path, long point, double slope, double bound, long window) {
  auto sample = [&](long j) { return std::clamp(path.curvature_sample(j), -bound, bound); };
  double upper = sample(point), lower = sample(point);
  for (long j = point - window; j <= point + window; ++j) {
    const double distance = slope * static_cast<double>(std::labs(j - point));
    upper = std::min(upper, sample(j) + distance);
    lower = std::max(lower, sample(j) - distance);
  }
  return 0.5 * (upper + lower);
}

TEST(CurvaturePreview, IsTheRateEnvelopeOfTheSamplesAtEachPoint) {
  const int cases = property_cases(200);
  for (int k = 0; k < cases; ++k) {
    const std::uint64_t seed = case_seed(k);
    Random random(seed);
    const bool closed = random.integer(0, 3) == 0;
    const double bound = random.uniform(0.02, 0.3);
    const Path path = random_piecewise_path(random, closed, bound);
    const double spacing = path.curvature_sample_spacing_m();
    const double step = random.uniform(0.1, 2.0);
    // Rates whose reach stays below max_preview_samples, so the window is the definition's.
    const double smallest_rate = bound / (0.9 * max_preview_samples * spacing);
    const double rate = smallest_rate * std::exp(random.uniform(0.0, std::log(200.0)));
    const double reach_m = bound / rate;
    // Half the cases within the reach of a curvature jump (where the envelope bites), the others
    // anywhere on the path and up to 30 m beyond either end, so that the window crosses them.
    const auto& jumps = path.curvature_jumps();
    const double s =
        random.coin() && !jumps.empty()
            ? jumps[static_cast<std::size_t>(random.integer(0, static_cast<int>(jumps.size()) - 1))]
                      .arc_length_m +
                  random.uniform(-1.2, 1.2) * reach_m
            : random.uniform(-30.0, path.length() + 30.0);
    SCOPED_TRACE(seed_message(seed) + " closed=" + std::to_string(closed) +
                 " s=" + std::to_string(s) + " step=" + std::to_string(step) +
                 " rate=" + std::to_string(rate) + " bound=" + std::to_string(bound));
    const PreviewedCurvature preview = preview_curvature(path, s, step, rate, bound);
    const long centre = std::lround(s / spacing);
    const long offset = std::max(1L, std::lround(step / spacing));
    const double slope = 2.0 * rate * spacing;
    // Beyond this many samples the slope term exceeds 2 bound, which no sample pair can.
    const long window = static_cast<long>(std::ceil(2.0 * bound / slope)) + 20;
    EXPECT_EQ(preview.before, envelope_midpoint(path, centre - offset, slope, bound, window));
    EXPECT_EQ(preview.at, envelope_midpoint(path, centre, slope, bound, window));
    EXPECT_EQ(preview.after, envelope_midpoint(path, centre + offset, slope, bound, window));
  }
}

TEST(CurvaturePreview, WithoutARateReadsTheThreeSamples) {
  const Path path = PathBuilder({0.0, 0.0}, 0.0).line(10.0).arc(20.0, 1.0).line(10.0).build();
  const double spacing = path.curvature_sample_spacing_m();
  for (const double s : {-5.0, 0.0, 9.9, 10.2, 25.0, 40.0, 60.0}) {
    const PreviewedCurvature preview = preview_curvature(path, s, 0.5, 0.0, 1.0);
    const long centre = std::lround(s / spacing);
    const long offset = std::max(1L, std::lround(0.5 / spacing));
    EXPECT_EQ(preview.before, path.curvature_sample(centre - offset)) << s;
    EXPECT_EQ(preview.at, path.curvature_sample(centre)) << s;
    EXPECT_EQ(preview.after, path.curvature_sample(centre + offset)) << s;
  }
}

}  // namespace
}  // namespace smoothsteer
