// The far law's length under the governor is derived (eq. governed_law_length) unless the
// parameters fix it: SteeringGovernor::fixed_law_length says which, law_length_m is the fixed
// length and nothing else. A length set while the choice is "derived" would do nothing, so
// validate() refuses it, naming both fields; the flat field (scenario key, Python) fixes the length
// as it sets it, so that the flat and the grouped way end in the same parameters.

#include <gtest/gtest.h>

#include <string>

#include "smoothsteer/controller/parameter_fields.hpp"
#include "smoothsteer/controller/steering_governor.hpp"

namespace smoothsteer {
namespace {

ControllerParameters governed() {
  ControllerParameters p;
  p.chain.order = 2;
  p.governor.enabled = true;
  p.governor.max_steering_rate_radps = 0.4;
  p.governor.max_steering_acceleration_radps2 = 8.0;
  return p;
}

void set_flat(ControllerParameters& p, const char* name, double value) {
  const ParameterField* field = find_parameter_field(name);
  ASSERT_NE(field, nullptr) << name;
  field->set(p, value);
}

TEST(FarLawLength, ALengthWithoutTheFixedChoiceIsRefusedNamingBothFields) {
  ControllerParameters p = governed();
  p.governor.law_length_m = 6.0;
  EXPECT_FALSE(p.is_valid());
  EXPECT_EQ(p.validation_error(),
            "ControllerParameters: governor.law_length_m = 6 has no effect while "
            "governor.fixed_law_length is false (the length is derived from the speed and the "
            "heading error, eq. governed_law_length)");
  p.governor.fixed_law_length = true;
  EXPECT_EQ(p.validation_error(), "");
}

TEST(FarLawLength, TheFixedChoiceNeedsALength) {
  ControllerParameters p = governed();
  p.governor.fixed_law_length = true;
  EXPECT_FALSE(p.is_valid());
  EXPECT_EQ(p.validation_error(),
            "ControllerParameters: governor.law_length_m = 0 must be > 0 m with "
            "governor.fixed_law_length = true (the far law's layer l kbar_sw / 2 needs a length)");
  p.governor.law_length_m = 1000.5;
  EXPECT_NE(p.validation_error().find("governor.law_length_m = 1000.5 must be in [0, 1000] m"),
            std::string::npos)
      << p.validation_error();
}

TEST(FarLawLength, WithoutTheGovernorBothFieldsAreInert) {
  ControllerParameters p;
  p.governor.fixed_law_length = true;
  EXPECT_EQ(p.validation_error(),
            "ControllerParameters: governor.fixed_law_length = 1 has no effect while "
            "governor.enabled is false");
}

TEST(FarLawLength, TheFlatFieldFixesTheLengthAsTheGroupedOnesDo) {
  ControllerParameters flat = governed();
  set_flat(flat, "governor.law_length_m", 6.0);
  ControllerParameters grouped = governed();
  grouped.governor.fixed_law_length = true;
  grouped.governor.law_length_m = 6.0;
  EXPECT_TRUE(flat.governor.fixed_law_length);
  EXPECT_EQ(flat.governor.law_length_m, 6.0);
  EXPECT_EQ(flat.validation_error(), grouped.validation_error());
  EXPECT_EQ(flat.validation_error(), "");
  // The flat 0 goes back to the derived length, as the grouped pair of defaults does.
  set_flat(flat, "governor.law_length_m", 0.0);
  EXPECT_FALSE(flat.governor.fixed_law_length);
  EXPECT_EQ(flat.validation_error(), "");
  // The choice's own flat field leaves the length where it is.
  set_flat(flat, "governor.fixed_law_length", 1.0);
  EXPECT_TRUE(flat.governor.fixed_law_length);
  EXPECT_EQ(flat.governor.law_length_m, 0.0);
  EXPECT_FALSE(flat.is_valid());
}

TEST(FarLawLength, TheLawUsesTheFixedLengthOrTheDerivedOne) {
  ControllerParameters p = governed();
  for (const double speed : {0.0, 5.0, 15.0, 30.0}) {
    for (const double heading : {0.0, 0.1, 0.6}) {
      SCOPED_TRACE("v=" + std::to_string(speed) + " psi=" + std::to_string(heading));
      p.governor.fixed_law_length = false;
      p.governor.law_length_m = 0.0;
      EXPECT_EQ(far_law_length(p, speed, heading), governed_law_length(p, speed, heading));
      p.governor.fixed_law_length = true;
      p.governor.law_length_m = 7.5;
      EXPECT_EQ(far_law_length(p, speed, heading), 7.5);
    }
  }
}

}  // namespace
}  // namespace smoothsteer
