// libFuzzer target: the scenario loader (YAML text -> validated Scenario, path and controller).
#include "fuzz_support.hpp"
#include "smoothsteer/evaluation/controller_registration.hpp"
#include "smoothsteer/runner/scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool registered = (smoothsteer::register_comparison_controllers(), true);
  (void)registered;
  const std::string file = smoothsteer::fuzz::write_scratch("scenario.yaml", data, size);
  smoothsteer::fuzz::expect_accept_or_reject([&] { smoothsteer::runner::load_scenario(file); });
  return 0;
}
