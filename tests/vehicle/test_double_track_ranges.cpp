// The double-track body's physical ranges: a roll inertia, stiffness or damping no car has is
// refused by name before a simulation would spend minutes on the roll mode it makes (a roll
// inertia of 1e-6 kg m^2 ran past 100 s for 2 s simulated, a damping of 1e9 cost 4 s per
// simulated second). The shipped vehicles and the ranges' edges stay accepted.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "smoothsteer/vehicle/vehicle_parameters.hpp"

namespace smoothsteer {
namespace {

VehicleParameters car() {
  VehicleParameters v;
  v.double_track = DoubleTrackParameters{};  // CommonRoad vehicle 2 with its mass
  return v;
}

std::string error_of(const std::function<void(DoubleTrackParameters&)>& change) {
  VehicleParameters v = car();
  change(*v.double_track);
  return v.validation_error();
}

struct Refused {
  const char* what;
  std::function<void(DoubleTrackParameters&)> change;
  const char* field;
  const char* rule;
};

TEST(DoubleTrackRanges, ValuesNoCarHasAreRefusedNamingTheField) {
  const Refused cases[] = {
      {"roll inertia 1e-6", [](DoubleTrackParameters& d) { d.roll_inertia_kgm2 = 1e-6; },
       "double_track.roll_inertia_kgm2 = 1e-06", "radius of gyration"},
      {"roll inertia 1e7", [](DoubleTrackParameters& d) { d.roll_inertia_kgm2 = 1e7; },
       "double_track.roll_inertia_kgm2", "radius of gyration"},
      {"rear roll damping 1e9", [](DoubleTrackParameters& d) { d.rear_roll_damping_nmsprad = 1e9; },
       "double_track.rear_roll_damping_nmsprad = 1e+09", "damping ratio"},
      {"front roll damping 1e9",
       [](DoubleTrackParameters& d) { d.front_roll_damping_nmsprad = 1e9; },
       "double_track.front_roll_damping_nmsprad = 1e+09", "damping ratio"},
      {"front roll stiffness 1e9",
       [](DoubleTrackParameters& d) { d.front_roll_stiffness_nmprad = 1e9; },
       "double_track.front_roll_stiffness_nmprad = 1e+09", "roll frequency"},
  };
  for (const Refused& c : cases) {
    const std::string error = error_of(c.change);
    EXPECT_NE(error.find(c.field), std::string::npos) << c.what << ": " << error;
    EXPECT_NE(error.find(c.rule), std::string::npos) << c.what << ": " << error;
  }
}

// The edges leave real cars a wide margin: a body at 0.15 and 0.9 track widths of gyration, a
// 9 Hz roll mode and a damping ratio of 4.5 are accepted.
TEST(DoubleTrackRanges, TheRangesEdgesAreAccepted) {
  const VehicleParameters v = car();
  const DoubleTrackParameters& d = *v.double_track;
  const double track = 0.5 * (d.front_track_m + d.rear_track_m);
  for (double gyration : {0.15, 0.9}) {
    const double inertia = v.mass_kg * std::pow(gyration * track, 2);
    EXPECT_EQ(error_of([&](DoubleTrackParameters& x) {
                x.roll_inertia_kgm2 = inertia;
                // Keep the frequency and the damping ratio of the default car.
                const double scale = inertia / d.roll_inertia_kgm2;
                x.front_roll_stiffness_nmprad *= scale;
                x.rear_roll_stiffness_nmprad *= scale;
                x.front_roll_damping_nmsprad *= scale;
                x.rear_roll_damping_nmsprad *= scale;
              }),
              "")
        << "gyration " << gyration;
  }
  const double two_pi = 6.283185307179586;
  const double stiffness = d.roll_inertia_kgm2 * std::pow(two_pi * 9.0, 2);
  EXPECT_EQ(error_of([&](DoubleTrackParameters& x) {
              x.front_roll_stiffness_nmprad = 0.5 * stiffness;
              x.rear_roll_stiffness_nmprad = 0.5 * stiffness;
            }),
            "");
  const double damping = 4.5 * 2.0 * std::sqrt(d.roll_stiffness_nmprad() * d.roll_inertia_kgm2);
  EXPECT_EQ(error_of([&](DoubleTrackParameters& x) {
              x.front_roll_damping_nmsprad = 0.5 * damping;
              x.rear_roll_damping_nmsprad = 0.5 * damping;
            }),
            "");
}

}  // namespace
}  // namespace smoothsteer
