// libFuzzer target: the vehicle loaders, for `tune` (load_vehicle_limits) and through a
// scenario's `vehicle: {file: ...}`.
#include "fuzz_support.hpp"
#include "smoothsteer/io/schedule_files.hpp"
#include "smoothsteer/runner/scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace smoothsteer;
  static const bool written = (fuzz::write_scratch("with_vehicle.yaml",
                                                   "path: {type: straight}\n"
                                                   "vehicle: {file: vehicle.yaml}\n"
                                                   "controller: {type: lead_wheel}\n"),
                               true);
  (void)written;
  const std::string file = fuzz::write_scratch("vehicle.yaml", data, size);
  fuzz::expect_accept_or_reject([&] { io::load_vehicle_limits(file); });
  fuzz::expect_accept_or_reject(
      [&] { runner::load_scenario((fuzz::scratch_directory() / "with_vehicle.yaml").string()); });
  return 0;
}
