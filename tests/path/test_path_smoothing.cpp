// Smoothing splines through noisy waypoints (Path::from_waypoints with a WaypointSmoothing):
// tolerance 0 is the interpolating spline, the fit keeps Reinsch's distance to the waypoints,
// and on jittered samples of a known curve its curvature is far closer to the curve's than the
// interpolating spline's, whose curvature reads the jitter.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/path/path.hpp"
#include "smoothsteer/path/path_builder.hpp"
#include "support/property.hpp"

namespace smoothsteer {
namespace {

TEST(PathSmoothing, ZeroToleranceIsTheInterpolatingSpline) {
  const std::vector<Vec2> waypoints{{0, 0}, {3, 1}, {5, 4}, {4, 8}, {7, 9}, {12, 9.5}};
  const Path interpolating = Path::from_waypoints(waypoints);
  const Path smoothed = Path::from_waypoints(waypoints, WaypointSmoothing{0.0});
  ASSERT_EQ(interpolating.segment_count(), smoothed.segment_count());
  EXPECT_EQ(interpolating.length(), smoothed.length());
  for (double s = 0.0; s <= interpolating.length(); s += 0.25) {
    const PathPoint a = interpolating.evaluate(s), b = smoothed.evaluate(s);
    EXPECT_EQ(a.position.x, b.position.x) << "s = " << s;
    EXPECT_EQ(a.position.y, b.position.y) << "s = " << s;
    EXPECT_EQ(a.curvature, b.curvature) << "s = " << s;
  }
}

TEST(PathSmoothing, RejectsABadToleranceNamingTheField) {
  const std::vector<Vec2> waypoints{{0, 0}, {1, 0}, {2, 0.1}};
  for (const double tolerance : {-0.1, std::numeric_limits<double>::quiet_NaN(),
                                 std::numeric_limits<double>::infinity(), 1e12}) {
    try {
      (void)Path::from_waypoints(waypoints, WaypointSmoothing{tolerance});
      ADD_FAILURE() << "accepted tolerance " << tolerance;
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find("smoothing.tolerance_m"), std::string::npos)
          << error.what();
    }
  }
}

//! Curvature error against the true curvature over the middle of the path (the natural ends
//! force zero curvature, at both fits alike), the RMS over samples every 0.5 m.
template <class TrueCurvature>
double rms_curvature_error(const Path& path, TrueCurvature true_curvature) {
  double sum = 0.0;
  int count = 0;
  for (double s = 0.2 * path.length(); s <= 0.8 * path.length(); s += 0.5) {
    const PathPoint point = path.evaluate(s);
    const double error = point.curvature - true_curvature(point.position);
    sum += error * error;
    ++count;
  }
  return std::sqrt(sum / count);
}

// Jittered samples (Gaussian, sigma 2-20 mm per coordinate, 1 m apart as a planner's window
// delivers them) of a random circle arc of radius 20-500 m, smoothed with Reinsch's tolerance
// sigma sqrt(2): the knots sit that close to the samples, the fitted path stays within a few
// sigma of the true circle, and its curvature error is a small fraction of the interpolating
// spline's.
TEST(PathSmoothing, JitteredArcKeepsTheCurvatureOfTheArc) {
  const int cases = testing::property_cases(40);
  double worst_ratio = 0.0, worst_interior = 0.0, worst_end = 0.0;
  for (int i = 0; i < cases; ++i) {
    const std::uint64_t seed = testing::case_seed(i);
    testing::Random random(seed + 38);
    const double radius = std::pow(10.0, random.uniform(std::log10(20.0), std::log10(500.0)));
    const double sigma = random.uniform(0.002, 0.02);
    const double length = random.uniform(60.0, 120.0);
    std::normal_distribution<double> jitter(0.0, sigma);
    std::vector<Vec2> samples;
    for (double s = 0.0; s <= length; s += 1.0) {
      const double angle = s / radius;
      const Vec2 on_circle{radius * std::sin(angle), radius * (1.0 - std::cos(angle))};
      samples.push_back(on_circle + Vec2{jitter(random.engine()), jitter(random.engine())});
    }
    const std::string context = testing::seed_message(seed) + "; radius " + std::to_string(radius) +
                                " m, sigma " + std::to_string(sigma) + " m, length " +
                                std::to_string(length) + " m";
    const double tolerance = sigma * std::sqrt(2.0);
    const Path interpolating = Path::from_waypoints(samples);
    // Reinsch's fit alone (with restore_corners, a tight arc's knots come closer still).
    const Path smoothed = Path::from_waypoints(samples, WaypointSmoothing{tolerance, false, false});
    // Reinsch's criterion: the RMS distance of the knots from the samples is the tolerance (the
    // mirror images that extend the ends are not counted), within the bisection's 15 %.

    const auto& segments = smoothed.segments();
    ASSERT_EQ(segments.size(), samples.size() - 1) << context;
    double sum = 0.0;
    for (std::size_t k = 0; k < samples.size(); ++k) {
      const double s = k < segments.size() ? segments[k].s0 : smoothed.length();
      const Vec2 d = smoothed.evaluate(s).position - samples[k];
      sum += d.x * d.x + d.y * d.y;
    }
    EXPECT_NEAR(std::sqrt(sum / static_cast<double>(samples.size())), tolerance, 0.15 * tolerance)
        << context;
    // Within a few sigma of the true circle; the ends less so: a natural spline ends straight,
    // and an end knot is averaged with neighbours on one side only. A planner's window starts
    // 5 m behind the car, so the car drives the interior.
    const Vec2 centre{0.0, radius};
    for (double s = 0.0; s <= smoothed.length(); s += 0.5) {
      const bool interior = s >= 5.0 && s <= smoothed.length() - 5.0;
      const double distance = std::abs(norm(smoothed.evaluate(s).position - centre) - radius);
      EXPECT_LE(distance, (interior ? 5.0 : 15.0) * sigma) << context << ", s = " << s;
      (interior ? worst_interior : worst_end) =
          std::max(interior ? worst_interior : worst_end, distance / sigma);
    }
    const auto on_arc = [&](Vec2) { return 1.0 / radius; };
    const double smoothed_error = rms_curvature_error(smoothed, on_arc);
    const double interpolated_error = rms_curvature_error(interpolating, on_arc);
    EXPECT_LE(smoothed_error, 0.25 * interpolated_error) << context;
    worst_ratio = std::max(worst_ratio, smoothed_error / interpolated_error);
  }
  std::printf(
      "worst smoothed / interpolated curvature error: %.3f; worst distance from the arc: "
      "%.2f sigma inside, %.2f sigma within 5 m of an end\n",
      worst_ratio, worst_interior, worst_end);
}

// A planner's window starts a few metres behind the car: 5 m into a window of jittered samples
// (sigma 2-20 mm, 1 m apart) of an arc of radius 20-1000 m, the fit's curvature is the arc's,
// without the bias a natural spline's straight end leaves there (with the mirror taken across a
// first fit's normal: -37 % of a 250 m arc's curvature at sigma 5 mm). Per case within 15 % of
// 1 / R plus the jitter's share; over the cases the mean relative error within 5 %.
TEST(PathSmoothing, FiveMetresIntoAJitteredWindowTheCurvatureIsTheArcs) {
  const int cases = testing::property_cases(40);
  double sum_relative = 0.0, worst_relative = 0.0;
  for (int i = 0; i < cases; ++i) {
    const std::uint64_t seed = testing::case_seed(i);
    testing::Random random(seed + 91);
    const double radius = std::pow(10.0, random.uniform(std::log10(20.0), std::log10(1000.0)));
    const double sigma = random.uniform(0.002, 0.02);
    const double direction = random.uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0;
    std::normal_distribution<double> jitter(0.0, sigma);
    std::vector<Vec2> samples;
    for (double s = 0.0; s <= 105.0; s += 1.0) {
      const double angle = s / radius;
      const Vec2 on_circle{radius * std::sin(angle), direction * radius * (1.0 - std::cos(angle))};
      samples.push_back(on_circle + Vec2{jitter(random.engine()), jitter(random.engine())});
    }
    const Path smoothed = Path::from_waypoints(samples, WaypointSmoothing{sigma * std::sqrt(2.0)});
    for (const double at : {5.0, smoothed.length() - 5.0}) {
      const double error = smoothed.evaluate(at).curvature - direction / radius;
      const std::string context = testing::seed_message(seed) + "; radius " +
                                  std::to_string(radius) + " m, sigma " + std::to_string(sigma) +
                                  " m, s = " + std::to_string(at) + " m, curvature error " +
                                  std::to_string(error) + " 1/m";
      EXPECT_LE(std::abs(error), 0.15 / radius + 0.08 * sigma) << context;
      sum_relative += error * radius * direction;
      worst_relative = std::max(worst_relative, std::abs(error) * radius);
    }
  }
  const double mean_relative = sum_relative / (2.0 * cases);
  EXPECT_LE(std::abs(mean_relative), 0.05);
  std::printf("5 m into the window: mean relative curvature error %.4f, worst %.3f\n",
              mean_relative, worst_relative);
}

//! Jittered samples, 1 m apart, of a road through a corner: `lead` m straight, clothoids of
//! radius / 4 into and out of an arc of `radius` turning by `turn` in total, 20 m straight.
struct JitteredCorner {
  Path road;
  std::vector<Vec2> samples;
};

JitteredCorner jittered_corner(double radius, double turn, double lead, double sigma,
                               testing::Random& random) {
  const double transition = 0.25 * radius;
  PathBuilder builder({0.0, 0.0}, 0.0);
  if (lead > 0.1) builder.line(lead);
  JitteredCorner corner{builder.clothoid(transition, std::copysign(1.0 / radius, turn))
                            .arc(radius, turn - std::copysign(transition / radius, turn))
                            .clothoid(transition, 0.0)
                            .line(20.0)
                            .build(),
                        {}};
  std::normal_distribution<double> jitter(0.0, sigma);
  for (double s = 0.0; s <= corner.road.length(); s += 1.0) {
    corner.samples.push_back(corner.road.evaluate(s).position +
                             Vec2{jitter(random.engine()), jitter(random.engine())});
  }
  return corner;
}

//! Largest distance of `fitted` from `road` over the fit's interior (5 m from each end) [m].
double largest_distance(const Path& fitted, const Path& road) {
  double largest = 0.0;
  for (double s = 5.0; s <= fitted.length() - 5.0; s += 0.25) {
    const Vec2 at = fitted.evaluate(s).position;
    largest = std::max(largest, norm(at - road.evaluate(road.project(at).arc_length_m).position));
  }
  return largest;
}

// A window through a tight corner (a parking bay, a hairpin: radius 5-15 m, turning 1.5-2.8 rad
// between clothoids, after a straight of 0-8 m; sigma 2-20 mm, 1 m apart): over the first 12 m,
// where a planner's window puts the car, the fit's curvature stays the road's. A cubic through
// the end's 21 waypoints cannot follow such a turn; its tangent, mirrored, bent the fit there
// (400 cases: mean relative error 0.21, worst 11; with the end's span limited to the turn 0.09
// and 0.17). Per case within 0.25 / R on average over the 12 m, over the cases within 0.12.
TEST(PathSmoothing, AWindowThroughATightCornerKeepsItsCurvature) {
  const int cases = testing::property_cases(40);
  double sum_relative = 0.0, worst_relative = 0.0;
  for (int i = 0; i < cases; ++i) {
    const std::uint64_t seed = testing::case_seed(i);
    testing::Random random(seed + 57);
    const double radius = random.uniform(5.0, 15.0);
    const double sigma = random.uniform(0.002, 0.02);
    const double turn = random.uniform(1.5, 2.8) * (random.uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0);
    const double lead = random.uniform(0.0, 8.0);
    const JitteredCorner corner = jittered_corner(radius, turn, lead, sigma, random);
    const std::vector<Vec2>& samples = corner.samples;
    const Path& road = corner.road;
    const Path smoothed = Path::from_waypoints(samples, WaypointSmoothing{sigma * std::sqrt(2.0)});
    double sum_error = 0.0;
    int count = 0;
    for (double s = 0.0; s <= 12.0; s += 0.25, ++count) {
      const PathPoint fitted = smoothed.evaluate(s);
      sum_error += std::abs(fitted.curvature - road.project(fitted.position).curvature);
    }
    const double relative = sum_error / count * radius;
    EXPECT_LE(relative, 0.25) << testing::seed_message(seed) << "; radius " << radius << " m, turn "
                              << turn << " rad, straight " << lead << " m, sigma " << sigma
                              << " m: mean |curvature error| over the first 12 m " << relative
                              << " / R";
    sum_relative += relative;
    worst_relative = std::max(worst_relative, relative);
  }
  EXPECT_LE(sum_relative / cases, 0.12);
  std::printf(
      "tight corner, first 12 m of the window: mean relative curvature error %.4f, "
      "worst %.3f\n",
      sum_relative / cases, worst_relative);
}

// Restoring the corners (twicing the fit): on jittered windows (sigma 1-5 cm, 1 m apart)
// through a corner of radius 8-45 m, Reinsch's fit cuts the corner by 1.5-3 sigma; with its
// residual's fit added the largest distance from the road shrinks to 0.54 of it on average
// (3000 cases). At worst it stays (1.003x, 0.8 rad around a 20 m radius with 2.4 cm: a cut of
// 1.7 sigma, where the jitter, not the cut, sets the largest distance).
TEST(PathSmoothing, RestoringTheCornersBringsTheFitCloserToTheRoad) {
  const int cases = testing::property_cases(40);
  double sum_ratio = 0.0, worst_ratio = 0.0;
  for (int i = 0; i < cases; ++i) {
    const std::uint64_t seed = testing::case_seed(i);
    testing::Random random(seed + 73);
    const double radius = random.uniform(8.0, 45.0);
    const double sigma = random.uniform(0.01, 0.05);
    const double turn = random.uniform(0.8, 2.8) * (random.uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0);
    const JitteredCorner corner =
        jittered_corner(radius, turn, random.uniform(10.0, 30.0), sigma, random);
    const double tolerance = sigma * std::sqrt(2.0);
    const double cut = largest_distance(
        Path::from_waypoints(corner.samples, WaypointSmoothing{tolerance, false, false}),
        corner.road);
    const double restored = largest_distance(
        Path::from_waypoints(corner.samples, WaypointSmoothing{tolerance}), corner.road);
    EXPECT_LE(restored, 1.1 * cut)
        << testing::seed_message(seed) << "; radius " << radius << " m, turn " << turn
        << " rad, sigma " << sigma << " m: largest distance from the road " << restored
        << " m restored, " << cut << " m cut";
    sum_ratio += restored / cut;
    worst_ratio = std::max(worst_ratio, restored / cut);
  }
  EXPECT_LE(sum_ratio / cases, 0.65);
  std::printf("restored / cut: mean %.3f, worst %.3f\n", sum_ratio / cases, worst_ratio);
}

// Corners are restored only where they are tight and the jitter large enough to cut them: a
// window whose fit stays gentler than a 50 m radius (radius 70-500 m), or whose tolerance is
// below that of 1 cm of jitter (a corner of radius 8-45 m), is Reinsch's fit bit for bit.
TEST(PathSmoothing, GentleRoadsAndSmallJitterAreNotRestored) {
  const int cases = testing::property_cases(40);
  for (int i = 0; i < cases; ++i) {
    const std::uint64_t seed = testing::case_seed(i);
    testing::Random random(seed + 29);
    const bool gentle = i % 2 == 0;
    const double radius = gentle ? random.uniform(70.0, 500.0) : random.uniform(8.0, 45.0);
    const double sigma = gentle ? random.uniform(0.01, 0.05) : random.uniform(0.001, 0.0098);
    const double turn = (gentle ? random.uniform(0.1, 0.6) : random.uniform(0.8, 2.8)) *
                        (random.uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0);
    const JitteredCorner corner =
        jittered_corner(radius, turn, random.uniform(10.0, 30.0), sigma, random);
    const WaypointSmoothing restoring{sigma * std::sqrt(2.0)};
    WaypointSmoothing alone = restoring;
    alone.restore_corners = false;
    const Path a = Path::from_waypoints(corner.samples, restoring);
    const Path b = Path::from_waypoints(corner.samples, alone);
    ASSERT_EQ(a.segment_count(), b.segment_count());
    for (std::size_t k = 0; k < a.segment_count(); ++k) {
      const PathPoint pa = a.evaluate(a.segments()[k].s0 + 0.5 * a.segments()[k].length);
      const PathPoint pb = b.evaluate(b.segments()[k].s0 + 0.5 * b.segments()[k].length);
      ASSERT_TRUE(pa.position.x == pb.position.x && pa.position.y == pb.position.y &&
                  pa.curvature == pb.curvature)
          << testing::seed_message(seed) << "; radius " << radius << " m, sigma " << sigma
          << " m, segment " << k;
    }
  }
}

// A fit's tolerance beyond the least-squares line's residual gives that line: samples of a
// straight line with jitter, smoothed with a large tolerance, give curvature ~ 0 everywhere.
TEST(PathSmoothing, LargeToleranceOnALineGivesTheLine) {
  std::mt19937_64 engine(7);
  std::normal_distribution<double> jitter(0.0, 0.01);
  std::vector<Vec2> samples;
  for (int k = 0; k <= 50; ++k) samples.push_back({static_cast<double>(k), jitter(engine)});
  const Path smoothed = Path::from_waypoints(samples, WaypointSmoothing{1.0});
  for (double s = 0.0; s <= smoothed.length(); s += 0.5) {
    EXPECT_LE(std::abs(smoothed.evaluate(s).curvature), 1e-4) << "s = " << s;
  }
}

}  // namespace
}  // namespace smoothsteer
