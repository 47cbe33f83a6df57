// libFuzzer target: the waypoint CSV reader and the path it builds.
#include "fuzz_support.hpp"
#include "smoothsteer/io/waypoint_csv.hpp"
#include "smoothsteer/path/path.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace smoothsteer;
  const std::string text(reinterpret_cast<const char*>(data), size);
  fuzz::expect_accept_or_reject(
      [&] { Path::from_waypoints(io::parse_waypoint_csv(text, "fuzz.csv")); });
  return 0;
}
