#pragma once
//! \file closed_loop_count.hpp
//! How many closed loops this process has run: every simulate() and run_kinematic_closed_loop()
//! call counts one. The test suite reports the total of a CI run (issue 12, item 7; scripts/
//! test.sh prints it). Thread safe.

namespace smoothsteer {

//! Closed loops started in this process so far.
long closed_loops_run() noexcept;

namespace detail {
//! Called once per closed loop by the simulators (and by tests that step a plant themselves).
void count_closed_loop() noexcept;
}  // namespace detail

}  // namespace smoothsteer
