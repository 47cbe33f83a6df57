// Progress and interruption of the long commands (docs/cli.md "Progress" and "Interrupt"), on the
// built binary: `compare lane-change` and `tune` over a long speed grid on a pseudo-terminal
// rewrite a count in place, without a terminal they print one summary line, with --quiet nothing;
// SIGINT during the run leaves the previous output as it was and exits with 130. No test here
// asserts a time.

#include <gtest/gtest.h>

#include <signal.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "apps/cli_process.hpp"
#include "apps/terminal_process.hpp"
#include "support/hang_watchdog.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer::testing {
namespace {

namespace fs = std::filesystem;

#ifndef SMOOTHSTEER_CLI
#define SMOOTHSTEER_CLI ""
#endif

class Progress : public ::testing::Test {
 protected:
  void SetUp() override {
    if (std::string(SMOOTHSTEER_CLI).empty()) GTEST_SKIP() << "apps not built";
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    directory_ = fs::temp_directory_path() /
                 ("smoothsteer_progress_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(directory_);
    fs::create_directories(directory_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(directory_, ignored);
  }
  //! `compare lane-change` on the shipped scenarios, its tables into DIR/out, plus `extra`.
  std::vector<std::string> lane_change(const std::vector<std::string>& extra = {}) const {
    std::vector<std::string> arguments{SMOOTHSTEER_CLI,
                                       "compare",
                                       "lane-change",
                                       "--out",
                                       (directory_ / "out").string(),
                                       "--scenarios",
                                       (source_dir() / "scenarios").string(),
                                       "--paper-figures",
                                       (source_dir() / "data/paper_figures.csv").string()};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    return arguments;
  }
  //! `tune` of the shipped car over `speeds`, its schedule into DIR/schedule.csv, plus `extra`.
  std::vector<std::string> tune(const std::string& speeds,
                                const std::vector<std::string>& extra = {}) const {
    std::vector<std::string> arguments{
        SMOOTHSTEER_CLI, "tune",
        "--vehicle",     (source_dir() / "vehicles/passenger_car.yaml").string(),
        "--speeds",      speeds,
        "--out",         (directory_ / "schedule.csv").string()};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    return arguments;
  }
  //! The speeds the written schedule holds (its rows below the header).
  std::size_t schedule_rows() const {
    const std::string text = read_text(directory_ / "schedule.csv");
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) - 1;
  }
  fs::path directory_;
};

//! A grid of some hundred speeds: long enough for a count, short enough for a test.
const std::string tune_grid = "1:30:0.1";
//! The longest grid `tune` takes (near its 10 000 speeds): the interrupt comes long before its end.
const std::string long_tune_grid = "1:30:0.003";

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::string line;
  for (const char c : text) {
    if (c == '\n') {
      lines.push_back(line);
      line.clear();
    } else {
      line += c;
    }
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

TEST_F(Progress, OnATerminalACountIsRewrittenInPlace) {
  const HangWatchdog watchdog("compare lane-change on a terminal", std::chrono::seconds(900));
  const TerminalResult result = run_on_terminal(lane_change(), directory_);
  ASSERT_EQ(result.exit_code, 0) << result.terminal;
  // Every update starts with a carriage return: "\rlane change: 7/48 runs, 2s elapsed, ~9s left".
  const std::regex update(R"(\rlane change: (\d+)/(\d+) runs, \S+ elapsed)");
  std::vector<int> counts;
  int total = -1;
  for (auto it = std::sregex_iterator(result.terminal.begin(), result.terminal.end(), update);
       it != std::sregex_iterator(); ++it) {
    counts.push_back(std::stoi((*it)[1]));
    total = std::stoi((*it)[2]);
  }
  ASSERT_GE(counts.size(), 2u) << result.terminal;
  EXPECT_EQ(counts.front(), 0) << result.terminal;
  EXPECT_EQ(counts.back(), total) << result.terminal;
  EXPECT_TRUE(std::is_sorted(counts.begin(), counts.end())) << result.terminal;
  EXPECT_EQ(result.terminal.find("runs in"), std::string::npos)  // no summary line as well
      << result.terminal;
}

TEST_F(Progress, WithoutATerminalOneSummaryLine) {
  const HangWatchdog watchdog("compare lane-change", std::chrono::seconds(900));
  const ProcessResult result = run_process(lane_change(), directory_);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::vector<std::string> lines = lines_of(result.err);
  ASSERT_EQ(lines.size(), 1u) << result.err;
  EXPECT_TRUE(std::regex_match(lines[0], std::regex(R"(lane change: \d+ runs in \d+ s)")))
      << lines[0];
  EXPECT_EQ(result.err.find('\r'), std::string::npos);
  EXPECT_TRUE(fs::exists(directory_ / "out" / "lane_change.csv"));
}

TEST_F(Progress, QuietPrintsNothingOnATerminalOrNot) {
  const HangWatchdog watchdog("compare lane-change --quiet", std::chrono::seconds(1800));
  const ProcessResult plain = run_process(lane_change({"--quiet"}), directory_);
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(plain.err, "");
  const TerminalResult terminal = run_on_terminal(lane_change({"-q"}), directory_);
  ASSERT_EQ(terminal.exit_code, 0) << terminal.terminal;
  EXPECT_EQ(terminal.terminal, "");
}

TEST_F(Progress, AnInterruptLeavesThePreviousTablesAndExits130) {
  const HangWatchdog watchdog("interrupted compare lane-change", std::chrono::seconds(900));
  fs::create_directories(directory_ / "out");
  const std::string previous_csv = "speed_mps,controller\n10,previous run\n";
  const std::string previous_md = "# the previous run's table\n";
  std::ofstream(directory_ / "out" / "lane_change.csv", std::ios::binary) << previous_csv;
  std::ofstream(directory_ / "out" / "lane_change.md", std::ios::binary) << previous_md;
  // The signal goes out once the first progress line shows that the work has started (not after
  // a fixed sleep).
  bool sent = false;
  const TerminalResult result =
      run_on_terminal(lane_change(), directory_, [&](pid_t child, const std::string& terminal) {
        if (!sent && terminal.find("lane change: 0/") != std::string::npos) {
          sent = ::kill(child, SIGINT) == 0;
        }
      });
  ASSERT_TRUE(sent) << result.terminal;
  EXPECT_EQ(result.exit_code, 130) << result.terminal;
  std::smatch match;
  ASSERT_TRUE(
      std::regex_search(result.terminal, match,
                        std::regex(R"(interrupted: (\d+) of (\d+) runs done; no table written)")))
      << result.terminal;
  EXPECT_LT(std::stoi(match[1]), std::stoi(match[2]));
  EXPECT_EQ(read_text(directory_ / "out" / "lane_change.csv"), previous_csv);
  EXPECT_EQ(read_text(directory_ / "out" / "lane_change.md"), previous_md);
  // No temporary file is left beside them either.
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(directory_ / "out")) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"lane_change.csv", "lane_change.md"}));
}

TEST_F(Progress, TuneCountsItsSpeedsInPlaceOnATerminal) {
  const HangWatchdog watchdog("tune on a terminal", std::chrono::seconds(900));
  const TerminalResult result = run_on_terminal(tune(tune_grid), directory_);
  ASSERT_EQ(result.exit_code, 0) << result.terminal;
  const std::regex update(R"(\rtune: (\d+)/(\d+) speeds, \S+ elapsed)");
  std::vector<std::size_t> counts;
  std::size_t total = 0;
  for (auto it = std::sregex_iterator(result.terminal.begin(), result.terminal.end(), update);
       it != std::sregex_iterator(); ++it) {
    counts.push_back(std::stoul((*it)[1]));
    total = std::stoul((*it)[2]);
  }
  ASSERT_GE(counts.size(), 2u) << result.terminal;
  EXPECT_EQ(counts.front(), 0u) << result.terminal;
  EXPECT_EQ(counts.back(), total) << result.terminal;
  EXPECT_TRUE(std::is_sorted(counts.begin(), counts.end())) << result.terminal;
  EXPECT_EQ(total, schedule_rows()) << "one count per speed of the schedule";
}

TEST_F(Progress, TuneWithoutATerminalPrintsOneSummaryLine) {
  const HangWatchdog watchdog("tune", std::chrono::seconds(900));
  const ProcessResult result = run_process(tune(tune_grid), directory_);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::vector<std::string> lines = lines_of(result.err);
  ASSERT_EQ(lines.size(), 1u) << result.err;
  std::smatch match;
  ASSERT_TRUE(std::regex_match(lines[0], match, std::regex(R"(tune: (\d+) speeds in \d+ s)")))
      << lines[0];
  EXPECT_EQ(std::stoul(match[1]), schedule_rows());
  EXPECT_NE(result.out.find("wrote "), std::string::npos) << "the summary stays on stdout";
}

TEST_F(Progress, TuneQuietPrintsNothingOnATerminalOrNot) {
  const HangWatchdog watchdog("tune --quiet", std::chrono::seconds(1800));
  const ProcessResult plain = run_process(tune(tune_grid, {"--quiet"}), directory_);
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(plain.err, "");
  const TerminalResult terminal = run_on_terminal(tune(tune_grid, {"-q"}), directory_);
  ASSERT_EQ(terminal.exit_code, 0) << terminal.terminal;
  EXPECT_EQ(terminal.terminal, "");
}

TEST_F(Progress, AnInterruptedTuneLeavesThePreviousScheduleAndExits130) {
  const HangWatchdog watchdog("interrupted tune", std::chrono::seconds(900));
  const std::string previous = "speed_mps\n10\n";
  std::ofstream(directory_ / "schedule.csv", std::ios::binary) << previous;
  bool sent = false;
  const TerminalResult result = run_on_terminal(
      tune(long_tune_grid), directory_, [&](pid_t child, const std::string& terminal) {
        if (!sent && terminal.find("tune: 0/") != std::string::npos) {
          sent = ::kill(child, SIGINT) == 0;
        }
      });
  ASSERT_TRUE(sent) << result.terminal;
  EXPECT_EQ(result.exit_code, 130) << result.terminal;
  std::smatch match;
  ASSERT_TRUE(std::regex_search(result.terminal, match,
                                std::regex(R"(interrupted: (\d+) of (\d+) speeds done)")))
      << result.terminal;
  EXPECT_LT(std::stoul(match[1]), std::stoul(match[2]));
  EXPECT_EQ(read_text(directory_ / "schedule.csv"), previous);
}

}  // namespace
}  // namespace smoothsteer::testing
