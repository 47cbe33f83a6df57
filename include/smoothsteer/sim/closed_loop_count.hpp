#pragma once
//! \file closed_loop_count.hpp
//! How many closed loops this process has run: every simulate() and run_kinematic_closed_loop()
//! call counts one. The test suite reports the total of a CI run (CI must show that it ran more
//! than 10^5 seeded closed loops; scripts/test.sh prints it). Thread safe.

namespace smoothsteer {

//! Closed loops started in this process so far.
long closed_loops_run() noexcept;

namespace detail {
//! Called once per closed loop by the simulators (and by tests that step a plant themselves).
void count_closed_loop() noexcept;
}  // namespace detail

}  // namespace smoothsteer
