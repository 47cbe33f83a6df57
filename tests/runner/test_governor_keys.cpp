// The scenario file's governor keys accept exactly what the field table accepts: the reader takes
// each number's range from the table (parameter_fields.cpp), so a file and the C++ API cannot
// disagree on a value (governor.margin = 0 was once refused in a file and valid in C++). Each
// range's ends and the values just beyond them are tried; a refusal names the key.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "smoothsteer/controller/parameter_fields.hpp"
#include "smoothsteer/io/config_section.hpp"
#include "smoothsteer/runner/scenario.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer::runner {
namespace {

// Whether the lane-change file loads with `controller.governor.<key> = value`; the refusal's
// message when it does not.
bool loads(const std::string& key, double value, std::string& message) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", value);
  try {
    load_scenario((testing::source_dir() / "scenarios/lane_change_15.yaml").string(),
                  {"controller.governor." + key + "=" + text});
    return true;
  } catch (const io::ConfigError& error) {
    message = error.what();
    return false;
  }
}

TEST(GovernorKeys, AcceptExactlyWhatTheFieldTableAccepts) {
  for (const std::string key : {"margin", "law_length_m", "max_longitudinal_acceleration_mps2"}) {
    const ParameterField* field = find_parameter_field("governor." + key);
    ASSERT_NE(field, nullptr) << key;
    const FieldRange& range = field->range;
    std::vector<double> values{range.min, range.max, 0.5 * (range.min + range.max)};
    values.push_back(std::nextafter(range.min, -INFINITY));
    values.push_back(std::nextafter(range.max, INFINITY));
    for (const double value : values) {
      if (!std::isfinite(value)) continue;
      SCOPED_TRACE(key + " = " + std::to_string(value));
      std::string message;
      const bool accepted = loads(key, value, message);
      EXPECT_EQ(accepted, range.contains(value)) << message;
      if (!accepted) {
        EXPECT_NE(message.find(key), std::string::npos) << message;
      }
    }
  }
  // The value that drifted: no reserve for the chain's variation is a valid choice.
  std::string message;
  EXPECT_TRUE(loads("margin", 0.0, message)) << message;
}

// A file that writes `governor: {law_length_m: 6}` fixes the far law's length at 6 m, as the key
// did when 0 meant "derived"; without the key the length stays derived.
TEST(GovernorKeys, ALawLengthKeyFixesTheLength) {
  const std::string file = (testing::source_dir() / "scenarios/lane_change_15.yaml").string();
  const auto governor = [&file](const std::vector<std::string>& overrides) {
    return make_scheduled_controller(load_scenario(file, overrides))
        ->controller()
        .parameters()
        .governor;
  };
  const SteeringGovernor fixed = governor({"controller.governor.law_length_m=6"});
  EXPECT_TRUE(fixed.fixed_law_length);
  EXPECT_EQ(fixed.law_length_m, 6.0);
  const SteeringGovernor derived = governor({});
  EXPECT_FALSE(derived.fixed_law_length);
  EXPECT_EQ(derived.law_length_m, 0.0);
  // The choice said explicitly overrides the key's.
  EXPECT_ANY_THROW(governor(
      {"controller.governor.law_length_m=6", "controller.governor.fixed_law_length=false"}));
}

}  // namespace
}  // namespace smoothsteer::runner
