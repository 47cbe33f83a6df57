#pragma once
//! Helpers for seeded randomized property tests. The number of cases comes from the environment
//! variable SMOOTHSTEER_PROPERTY_CASES (default given by the caller); the base seed from
//! SMOOTHSTEER_SEED (default 20240607). Every case derives its own seed, which failing
//! assertions print so the case can be replayed alone with SMOOTHSTEER_SEED=<seed> and
//! SMOOTHSTEER_PROPERTY_CASES=1.

#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>

namespace smoothsteer::testing {

inline int property_cases(int default_count = 40) {
  if (const char* env = std::getenv("SMOOTHSTEER_PROPERTY_CASES")) {
    const int count = std::atoi(env);
    if (count > 0) return count;
  }
  return default_count;
}

inline std::uint64_t base_seed() {
  if (const char* env = std::getenv("SMOOTHSTEER_SEED")) return std::strtoull(env, nullptr, 10);
  return 20240607ULL;
}

//! Seed of case `index`: the base seed for case 0, so that a reported seed replays directly.
inline std::uint64_t case_seed(int index) {
  return base_seed() + 7919ULL * static_cast<std::uint64_t>(index);
}

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  double uniform(double low, double high) {
    return std::uniform_real_distribution<double>(low, high)(engine_);
  }
  int integer(int low, int high) { return std::uniform_int_distribution<int>(low, high)(engine_); }
  bool coin() { return integer(0, 1) == 1; }
  std::mt19937_64& engine() { return engine_; }

 private:
  std::mt19937_64 engine_;
};

//! The replay line of case `seed` = case_seed(k). A test that draws from an offset stream
//! (Random(seed + offset), to decorrelate it from other tests) still prints the unoffset seed,
//! which replays the case as case 0.
inline std::string seed_message(std::uint64_t seed) {
  return "replay with SMOOTHSTEER_SEED=" + std::to_string(seed) + " SMOOTHSTEER_PROPERTY_CASES=1";
}

}  // namespace smoothsteer::testing
