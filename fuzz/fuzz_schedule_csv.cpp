// libFuzzer target: the gain-schedule CSV reader (`controller.schedule`, docs/tuning.md).
#include "fuzz_support.hpp"
#include "smoothsteer/io/schedule_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace smoothsteer;
  const std::string file = fuzz::write_scratch("schedule.csv", data, size);
  fuzz::expect_accept_or_reject([&] { io::read_schedule_csv(file); });
  return 0;
}
