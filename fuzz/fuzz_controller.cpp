// libFuzzer target: the library below the readers. The input is a ControllerParameters (every
// field, the enumerations as raw integers) and a sequence of calls: update() with any input,
// reset(), set_matched_disturbance(), set_path() and retune(). Invalid parameters must be
// refused with a message; a controller built from valid ones must answer every call with a
// status, leave its output alone unless ok, and give a finite output with ok. UBSan catches
// what the arithmetic does with the rest (a float-to-int overflow of the sub-step count was
// one).
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>

#include "fuzz_support.hpp"
#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/path/path_builder.hpp"

namespace {

using namespace smoothsteer;

//! Reads values from the fuzzer's bytes; past the end it gives zeros.
class Reader {
 public:
  Reader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t byte() { return used_ < size_ ? data_[used_++] : 0; }
  bool empty() const { return used_ >= size_; }
  //! A value from a table of edge cases (zero, subnormal, huge, inf, NaN, the bounds of the
  //! rules) for a selector byte < 64, else eight raw bytes: as they are for a selector >= 160,
  //! with their magnitude moved into [1/16, 8) (near the defaults) below that.
  double real() {
    static constexpr double inf = std::numeric_limits<double>::infinity();
    static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    static constexpr double special[] = {
        0.0, -0.0, 1e-308, -1e-308, 4.9e-324, 1e308, -1e308, inf, -inf,  nan, 1.0, -1.0,
        0.5, 0.01, 100.0,  1e-3,    1e3,      1e9,   -1e9,   1e6, 0.999, 2.7, 0.2, 1.5707963};
    const std::uint8_t selector = byte();
    if (selector < 64) return special[selector % (sizeof special / sizeof special[0])];
    std::uint64_t bits = 0;
    for (int k = 0; k < 8; ++k) bits = (bits << 8) | byte();
    double value = 0.0;
    std::memcpy(&value, &bits, sizeof value);
    if (selector < 160 && std::isfinite(value)) {  // a number near the defaults: mantissa only
      int exponent = 0;
      return std::ldexp(std::frexp(value, &exponent), static_cast<int>(selector % 8) - 3);
    }
    return value;
  }
  int integer() {
    std::uint32_t bits = 0;
    for (int k = 0; k < 4; ++k) bits = (bits << 8) | byte();
    const std::uint8_t mode = byte() % 4;
    if (mode == 0) return static_cast<int>(bits);  // anything
    return static_cast<int>(bits % 16) - 3;        // small, some negative
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t used_ = 0;
};

ControllerParameters read_parameters(Reader& in) {
  ControllerParameters p;
  // A field is overwritten only when its flag byte is odd, so that the defaults stay reachable.
  auto maybe = [&in](auto& field, auto read) {
    if (in.byte() & 1u) field = read();
  };
  auto real = [&in] { return in.real(); };
  auto integer = [&in] { return in.integer(); };
  auto flag = [&in] { return (in.byte() & 1u) != 0; };
  maybe(p.chain.order, integer);
  maybe(p.chain.vehicle_wheelbase_m, real);
  for (double& lambda : p.chain.wheelbases_m) maybe(lambda, real);
  maybe(p.chain.lead_curvature_bound, real);
  maybe(p.law.k_rob, real);
  maybe(p.law.approach_angle_rad, real);
  maybe(p.feedforward.share, real);
  maybe(p.feedforward.curvature_rate, real);
  maybe(p.feedforward.catch_up, real);
  maybe(p.law.boundary_layer, real);
  maybe(p.delay_compensation.actuator_delay_s, real);
  maybe(p.single_track.preview_time_s, real);
  maybe(p.disturbance_estimation.length_m, real);
  maybe(p.single_track.rear_slip_gradient_s2pm, real);
  maybe(p.single_track.front_slip_gradient_s2pm, real);
  maybe(p.single_track.second_order, flag);
  maybe(p.friction_guard.max_lateral_acceleration_mps2, real);
  maybe(p.actuator_inversion.time_constant_s, real);
  maybe(p.actuator_inversion.lag_count, integer);
  maybe(p.law.surface, [&in] { return static_cast<SlidingSurface>(in.integer()); });
  maybe(p.feedforward.cornering_target,
        [&in] { return static_cast<CorneringTarget>(in.integer()); });
  maybe(p.feedforward.curvature_preview,
        [&in] { return static_cast<CurvaturePreview>(in.integer()); });
  maybe(p.chain.max_substep_fraction, real);
  maybe(p.chain.max_substeps, integer);
  // The optional groups' switches, so that inconsistent flags reach validate() as well.
  maybe(p.delay_compensation.enabled, flag);
  maybe(p.single_track.enabled, flag);
  maybe(p.disturbance_estimation.enabled, flag);
  maybe(p.friction_guard.enabled, flag);
  maybe(p.actuator_inversion.enabled, flag);
  return p;
}

const std::shared_ptr<const Path>& path(std::uint8_t which) {
  static const std::shared_ptr<const Path> paths[] = {
      std::make_shared<const Path>(Path::straight_line({0.0, 0.0}, 0.0, 200.0)),
      std::make_shared<const Path>(Path::circle({0.0, 20.0}, 20.0)),
      std::make_shared<const Path>(
          PathBuilder({0.0, 0.0}, 0.0).line(10.0).arc(8.0, 1.5).line(5.0).arc(12.0, -2.0).build()),
      std::make_shared<const Path>(
          Path::from_waypoints({{0.0, 0.0}, {10.0, 1.0}, {20.0, -2.0}, {30.0, 4.0}})),
  };
  return paths[which % 4];
}

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "fuzz_controller: %s\n", what);
  std::abort();
}

//! Bitwise equal fields (the struct's padding is not compared).
bool same(const ControllerOutput& a, const ControllerOutput& b) {
  const auto equal = [](double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; };
  return equal(a.steering_angle_rad, b.steering_angle_rad) &&
         equal(a.steering_rate_radps, b.steering_rate_radps) &&
         equal(a.steering_acceleration_radps2, b.steering_acceleration_radps2) &&
         a.derivatives_available == b.derivatives_available &&
         std::memcmp(&a.diagnostics, &b.diagnostics, sizeof a.diagnostics) == 0;
}

void check_rules_agree(const ControllerParameters& p) {
  const std::string message = p.validation_error();
  if (p.is_valid() != message.empty()) fail("is_valid() and validation_error() disagree");
  bool threw = false;
  try {
    p.validate();
  } catch (const std::invalid_argument& error) {
    threw = true;
    if (error.what()[0] == '\0') fail("validate() threw without a message");
  }
  if (threw == message.empty()) fail("validate() and validation_error() disagree");
}

void run(Reader& in) {
  const ControllerParameters parameters = read_parameters(in);
  check_rules_agree(parameters);
  if (!parameters.is_valid()) return;
  LeadWheelController controller(parameters, path(in.byte()));
  ControllerOutput output;
  for (int call = 0; call < 64 && !in.empty(); ++call) {
    switch (in.byte() % 8) {
      case 0:
        controller.reset(in.real());
        break;
      case 1:
        controller.set_matched_disturbance(in.real());
        break;
      case 2:
        controller.set_path(path(in.byte()));
        break;
      case 3: {
        const ControllerParameters retuned = read_parameters(in);
        check_rules_agree(retuned);
        const Status status = controller.retune(retuned);
        if (!retuned.is_valid() && status == Status::ok) fail("retune() took invalid parameters");
        break;
      }
      default: {
        ControllerInput input;
        input.rear_axle_position = {in.real(), in.real()};
        input.heading_rad = in.real();
        input.speed_mps = in.real();
        input.acceleration_mps2 = in.real();
        input.period_s = in.real();
        input.rear_axle_side_slip_rad = in.real();
        const ControllerOutput before = output;
        const Status status = controller.update(input, output);
        if (status == Status::ok) {
          if (!all_finite(output)) fail("update() returned ok with a non-finite output");
        } else if (!same(before, output)) {
          fail("update() changed its output without ok");
        }
        if (!input_in_range(input) && status != Status::invalid_input) {
          fail("update() did not refuse an input outside ControllerInputRange");
        }
      }
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Reader in(data, size);
  smoothsteer::fuzz::expect_accept_or_reject([&] { run(in); });
  return 0;
}
