// libFuzzer target: `--set key.path=value` parsing. Each input line is one override, applied to
// a valid scenario that is then loaded (so the overridden values pass every check).
#include <sstream>
#include <vector>

#include "fuzz_support.hpp"
#include "smoothsteer/runner/scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace smoothsteer;
  static const bool written = (fuzz::write_scratch("base.yaml",
                                                   "name: base\n"
                                                   "path: {type: lane_change}\n"
                                                   "speed: {initial_mps: 10}\n"
                                                   "controller: {type: lead_wheel}\n"),
                               true);
  (void)written;
  std::vector<std::string> overrides;
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  for (std::string line; std::getline(lines, line) && overrides.size() < 16;) {
    overrides.push_back(line);
  }
  fuzz::expect_accept_or_reject([&] {
    runner::load_scenario((fuzz::scratch_directory() / "base.yaml").string(), overrides);
  });
  return 0;
}
