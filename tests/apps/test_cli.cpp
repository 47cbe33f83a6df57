// The command-line tools under hostile input: regression tests of the defects that adversarial
// testing found and that need the real binaries, a working directory and processes.

#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "apps/cli_process.hpp"
#include "support/hang_watchdog.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer::testing {
namespace {

namespace fs = std::filesystem;

#ifndef SMOOTHSTEER_CLI
#define SMOOTHSTEER_CLI ""
#define SMOOTHSTEER_DEMO ""
#endif

std::string scenario(const std::string& name) {
  return (source_dir() / "scenarios" / name).string();
}

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    if (std::string(SMOOTHSTEER_CLI).empty()) GTEST_SKIP() << "apps not built";
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    directory_ = fs::temp_directory_path() /
                 ("smoothsteer_cli_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(directory_);
    fs::create_directories(directory_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(directory_, ignored);
  }
  ProcessResult cli(std::vector<std::string> arguments,
                    const std::vector<std::string>& environment = {}) {
    arguments.insert(arguments.begin(), SMOOTHSTEER_CLI);
    return run_process(arguments, directory_, environment);
  }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(directory_ / name, std::ios::binary) << text;
    return (directory_ / name).string();
  }
  fs::path directory_;
};

// --out is an argument of the plotter, never shell text.
TEST_F(Cli, PlotPassesTheOutputDirectoryWithoutAShell) {
  const std::string fake = write("fake_plot.py",
                                 "import sys\n"
                                 "open(sys.argv[2], 'w').write('png')\n"
                                 "open(sys.argv[2] + '.args', 'w').write('\\n'.join(sys.argv))\n");
  const std::string hostile = "x'; touch INJECTED; echo '";
  const ProcessResult run = cli({"run", scenario("lane_change_10.yaml"), "--out", hostile, "--plot",
                                 "--set", "simulation.duration_s=1"},
                                {"SMOOTHSTEER_PLOT_SCRIPT=" + fake});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_FALSE(fs::exists(directory_ / "INJECTED")) << "the shell ran `touch INJECTED`";
  EXPECT_TRUE(fs::exists(directory_ / hostile / "trace.png")) << run.out << run.err;
  EXPECT_TRUE(fs::exists(directory_ / hostile / "trace.csv"));
}

// The script is found relative to the binary/source tree from any directory.
TEST_F(Cli, PlotWorksFromAnyWorkingDirectory) {
  if (run_process({"/usr/bin/python3", "-c", "import matplotlib"}, directory_).exit_code != 0) {
    GTEST_SKIP() << "python3-matplotlib is not installed";
  }
  const ProcessResult run = cli({"run", scenario("lane_change_10.yaml"), "--out", "plotted",
                                 "--plot", "--set", "simulation.duration_s=2"},
                                {"SMOOTHSTEER_PLOT_SCRIPT"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(fs::exists(directory_ / "plotted" / "trace.png")) << run.out << run.err;
}

// Parse errors and --version: exit codes 1 and 0, not CLI11's.
TEST_F(Cli, ParseErrorsExitOneAndVersionPrints) {
  EXPECT_EQ(cli({"run"}).exit_code, 1);
  EXPECT_EQ(cli({"--no-such-option"}).exit_code, 1);
  EXPECT_EQ(cli({"run", scenario("lane_change_10.yaml"), "--out"}).exit_code, 1);
  EXPECT_EQ(cli({"tune", "--vehicle", "x.yaml", "--out", "s.csv", "--order", "two"}).exit_code, 1);
  const ProcessResult version = cli({"--version"});
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_NE(version.out.find("smoothsteer 0."), std::string::npos) << version.out;
  EXPECT_EQ(cli({"--help"}).exit_code, 0);
}

// A baseline's set-up rule (ComparisonSetup) and gains name the scenario and the key.
TEST_F(Cli, BaselineErrorsNameTheScenarioAndTheKey) {
  const std::string file = scenario("lane_change_15.yaml");
  const ProcessResult setup =
      cli({"run", file, "--out", "o", "--set", "controller.type=proposed_c1", "--set",
           "controller.lead_wheelbase_m=5"});
  EXPECT_EQ(setup.exit_code, 1);
  for (const char* part : {"lane_change_15.yaml", "'controller'",
                           "ComparisonSetup: "
                           "lead_wheelbase_m = 5"}) {
    EXPECT_NE(setup.err.find(part), std::string::npos) << part << " missing in " << setup.err;
  }
  const ProcessResult gain = cli({"run", file, "--out", "o", "--set", "controller.type=lqr",
                                  "--set", "controller.weight_lateral=-1"});
  EXPECT_EQ(gain.exit_code, 1);
  for (const char* part : {"lane_change_15.yaml", "'controller.weight_lateral'", "out of range"}) {
    EXPECT_NE(gain.err.find(part), std::string::npos) << part << " missing in " << gain.err;
  }
}

TEST_F(Cli, DemoHelpWritesNoTraceFile) {
  const ProcessResult help = run_process({SMOOTHSTEER_DEMO, "--help"}, directory_);
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("usage"), std::string::npos);
  EXPECT_FALSE(fs::exists(directory_ / "--help"));
}

// An output that exists and is not a regular file is refused, not renamed over.
TEST_F(Cli, OutputsThatAreNotRegularFilesAreRefused) {
  const fs::path fifo = directory_ / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const ProcessResult tune =
      cli({"tune", "--vehicle", (source_dir() / "vehicles/passenger_car.yaml").string(), "--speeds",
           "5:6:1", "--out", fifo.string()});
  EXPECT_EQ(tune.exit_code, 1);
  EXPECT_NE(tune.err.find("--out '" + fifo.string() + "'"), std::string::npos) << tune.err;
  EXPECT_NE(tune.err.find("not a regular file"), std::string::npos) << tune.err;
  const ProcessResult sweep = cli({"sweep", scenario("lane_change_10.yaml"), "--out", fifo.string(),
                                   "--vary", "controller.k_rob=0.2"});
  EXPECT_EQ(sweep.exit_code, 1);
  EXPECT_NE(sweep.err.find("not a regular file"), std::string::npos) << sweep.err;
  EXPECT_TRUE(fs::is_fifo(fifo));
  const ProcessResult run = cli({"run", scenario("lane_change_10.yaml"), "--out", fifo.string()});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("not a directory"), std::string::npos) << run.err;
  EXPECT_TRUE(fs::is_fifo(fifo));
}

// A run's outputs appear together or not at all.
TEST_F(Cli, FailedRunLeavesThePreviousOutputsWhole) {
  ASSERT_EQ(cli({"run", scenario("lane_change_10.yaml"), "--out", "out", "--set",
                 "simulation.duration_s=1"})
                .exit_code,
            0);
  const std::string summary = read_text(directory_ / "out/summary.json");
  const std::string bad = write("bad.yaml",
                                "name: bad\ndescription: \"caf\xe9\"\npath: {type: straight}\n"
                                "controller: {type: lead_wheel}\n");
  const ProcessResult run = cli({"run", bad, "--out", "out"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("bad.yaml: not valid UTF-8 at line 2"), std::string::npos) << run.err;
  EXPECT_EQ(read_text(directory_ / "out/summary.json"), summary);
  for (const auto& entry : fs::directory_iterator(directory_)) {
    EXPECT_EQ(entry.path().filename().string().find(".partial"), std::string::npos)
        << "left behind: " << entry.path();
  }
}

TEST_F(Cli, KilledRunPublishesNothingAndItsLeftoversAreRemoved) {
  const std::vector<std::string> arguments{SMOOTHSTEER_CLI,
                                           "run",
                                           scenario("lane_change_10.yaml"),
                                           "--out",
                                           "long",
                                           "--set",
                                           "simulation.stop_at_path_end=false",
                                           "--set",
                                           "simulation.duration_s=3600"};
  const pid_t child =
      start_process(arguments, directory_, {}, directory_ / "o.txt", directory_ / "e.txt");
  ASSERT_GT(child, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ::kill(child, SIGKILL);
  wait_process(child);
  EXPECT_FALSE(fs::exists(directory_ / "long"));
  ASSERT_EQ(cli({"run", scenario("lane_change_10.yaml"), "--out", "long", "--set",
                 "simulation.duration_s=1"})
                .exit_code,
            0);
  EXPECT_TRUE(fs::exists(directory_ / "long/summary.json"));
  for (const auto& entry : fs::directory_iterator(directory_)) {
    EXPECT_EQ(entry.path().filename().string().find(".partial"), std::string::npos)
        << "left behind: " << entry.path();
  }
}

TEST_F(Cli, OutputDirectoryWithOtherFilesIsRefused) {
  fs::create_directories(directory_ / "mine");
  write("mine/thesis.tex", "precious");
  const ProcessResult run = cli({"run", scenario("lane_change_10.yaml"), "--out", "mine"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("'thesis.tex'"), std::string::npos) << run.err;
  EXPECT_EQ(read_text(directory_ / "mine/thesis.tex"), "precious");
}

// Counts the input controls are capped before anything is built.
TEST_F(Cli, HugeCountsAreRefusedWithTheOption) {
  const ProcessResult speeds =
      cli({"tune", "--vehicle", (source_dir() / "vehicles/passenger_car.yaml").string(), "--speeds",
           "1:1e300:1e-300", "--out", "s.csv"});
  EXPECT_EQ(speeds.exit_code, 1);
  EXPECT_NE(speeds.err.find("--speeds"), std::string::npos) << speeds.err;
  std::vector<std::string> sweep{"sweep", scenario("lane_change_10.yaml"), "--out", "t.csv"};
  for (int axis = 0; axis < 30; ++axis) {
    sweep.push_back("--vary");
    sweep.push_back("controller.k_rob=0.2,0.3");
  }
  const ProcessResult grid = cli(sweep);
  EXPECT_EQ(grid.exit_code, 1);
  EXPECT_NE(grid.err.find("--vary"), std::string::npos) << grid.err;
  EXPECT_FALSE(fs::exists(directory_ / "t.csv"));
}

// A sweep whose every row fails is an error.
// The paper's Sec. IV-A study runs on the shipped circle_sections_paper.yaml, as the README and
// docs/cli.md show it: the four variations and the parameter table, every run ok.
TEST_F(Cli, PaperVariationsRunOnTheShippedPaperScenario) {
  const ProcessResult sweep = cli({"sweep", scenario("circle_sections_paper.yaml"), "--paper",
                                   "--out", "variations.csv", "--set", "simulation.duration_s=5"});
  EXPECT_EQ(sweep.exit_code, 0) << sweep.err;
  EXPECT_NE((sweep.out + sweep.err).find("4 runs, 0 failed"), std::string::npos) << sweep.out;
}

TEST_F(Cli, SweepWithEveryRowFailingExitsOne) {
  const ProcessResult sweep = cli({"sweep", scenario("lane_change_10.yaml"), "--out", "t.csv",
                                   "--vary", "controller.k_rob=5,7"});
  EXPECT_EQ(sweep.exit_code, 1);
  EXPECT_NE(sweep.err.find("every run failed"), std::string::npos) << sweep.err;
  EXPECT_NE(sweep.err.find("controller.k_rob"), std::string::npos) << sweep.err;
}

// Streaming traces: peak memory does not grow with the run's length (a 600 s run
// within 1.3 times a 10 s run). Sanitizer builds keep freed memory in quarantine: skipped there.
TEST_F(Cli, PeakMemoryDoesNotGrowWithTheDuration) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "ASan's quarantine makes RSS grow with allocations";
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  GTEST_SKIP() << "ASan's quarantine makes RSS grow with allocations";
#endif
#endif
  long peak_kb[2] = {0, 0};
  const char* durations[2] = {"10", "600"};
  for (int i = 0; i < 2; ++i) {
    const pid_t child = start_process(
        {SMOOTHSTEER_CLI, "run", scenario("lane_change_10.yaml"), "--out",
         std::string("m") + durations[i], "--set", "path={type: circle, radius_m: 50}", "--set",
         std::string("simulation.duration_s=") + durations[i]},
        directory_, {}, directory_ / "o.txt", directory_ / "e.txt");
    ASSERT_EQ(wait_process(child, &peak_kb[i]), 0) << read_text(directory_ / "e.txt");
  }
  EXPECT_LE(static_cast<double>(peak_kb[1]), 1.3 * static_cast<double>(peak_kb[0]))
      << "10 s: " << peak_kb[0] << " kB, 600 s: " << peak_kb[1] << " kB";
  EXPECT_GT(fs::file_size(directory_ / "m600/trace.csv"),
            50 * fs::file_size(directory_ / "m10/trace.csv"));
}

// Messages that named nothing: the controller error says when and which input, and a legal
// --out of 255 bytes works.
TEST_F(Cli, ControllerErrorsSayWhenAndWhy) {
  // Heading away from the path, so that the car leaves the input range in the first period
  // whatever the controller steers.
  const ProcessResult run =
      cli({"run", scenario("lane_change_10.yaml"), "--out", "o", "--set", "start.y_m=1e9", "--set",
           "start.heading_rad=1.5", "--set", "simulation.duration_s=1"});
  EXPECT_EQ(run.exit_code, 1);
  for (const char* part : {"controller_error", "at t = ", "invalid_input", "rear_axle_position.y",
                           "ControllerInputRange", "1e+09"}) {
    EXPECT_NE(run.err.find(part), std::string::npos) << part << " missing in " << run.err;
  }
}

TEST_F(Cli, LongestLegalOutputNamesWork) {
  const std::string name(255, 'o');
  const ProcessResult run = cli({"run", scenario("lane_change_10.yaml"), "--out", name, "--set",
                                 "simulation.duration_s=0.2"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(fs::exists(directory_ / name / "summary.json"));
  const ProcessResult tune =
      cli({"tune", "--vehicle", (source_dir() / "vehicles/passenger_car.yaml").string(), "--speeds",
           "5:6:1", "--out", std::string(255, 't')});
  EXPECT_EQ(tune.exit_code, 0) << tune.err;
  EXPECT_TRUE(fs::exists(directory_ / std::string(255, 't')));
}

// The tuner's inputs: a directory, a FIFO, or a value run refuses.
TEST_F(Cli, TuneRefusesWhatIsNotAVehicleFile) {
  const ProcessResult directory =
      cli({"tune", "--vehicle", directory_.string(), "--speeds", "5:6:1", "--out", "s.csv"});
  EXPECT_EQ(directory.exit_code, 1);
  EXPECT_NE(directory.err.find("is a directory"), std::string::npos) << directory.err;
  EXPECT_EQ(directory.err.find("filesystem"), std::string::npos) << directory.err;
  const fs::path fifo = directory_ / "fifo.yaml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  ProcessResult pipe;
  {
    const testing::HangWatchdog watchdog("tune --vehicle FIFO");  // opening it would block
    pipe = cli({"tune", "--vehicle", fifo.string(), "--speeds", "5:6:1", "--out", "s.csv"});
  }
  EXPECT_EQ(pipe.exit_code, 1);
  EXPECT_NE(pipe.err.find("not a regular file"), std::string::npos) << pipe.err;
  std::string car = read_text(source_dir() / "vehicles/passenger_car.yaml");
  const std::size_t b = car.find("stiffness_factor_b: 15.47");
  ASSERT_NE(b, std::string::npos);
  car.replace(b, 25, "stiffness_factor_b: .nan");
  const ProcessResult nan =
      cli({"tune", "--vehicle", write("nan.yaml", car), "--speeds", "5:6:1", "--out", "s.csv"});
  EXPECT_EQ(nan.exit_code, 1);
  EXPECT_NE(nan.err.find("'front_tire.stiffness_factor_b'"), std::string::npos) << nan.err;
  const ProcessResult cycle = cli({"tune", "--vehicle", write("cycle.yaml", "a: &a [*a]\n"),
                                   "--speeds", "5:6:1", "--out", "s.csv"});
  EXPECT_EQ(cycle.exit_code, 1);
  EXPECT_NE(cycle.err.find("cycle"), std::string::npos) << cycle.err;
}

TEST_F(Cli, SummaryWritesCountsAsIntegersAndTheToolVersion) {
  ASSERT_EQ(cli({"run", scenario("lane_change_10.yaml"), "--out", "o", "--set",
                 "simulation.duration_s=1"})
                .exit_code,
            0);
  const std::string summary = read_text(directory_ / "o/summary.json");
  EXPECT_NE(summary.find("\"steps\": 51\n"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"bound_violations\": 0"), std::string::npos);
  EXPECT_NE(summary.find("\"commit\":"), std::string::npos);
  EXPECT_NE(summary.find("\"version\": \"0."), std::string::npos);
}

// Every committed schedule is what the `smoothsteer tune` command written in its
// scenario file produces, byte for byte (the command runs from the repository root).
TEST_F(Cli, CommittedSchedulesAreRegeneratedByTheCommandInTheirScenario) {
  int checked = 0;
  std::vector<fs::path> files;  // the scenarios and the road suite (parking_lot's schedule)
  for (const char* folder : {"scenarios", "scenarios/roads"}) {
    for (const auto& entry : fs::directory_iterator(source_dir() / folder)) {
      if (entry.path().extension() == ".yaml") files.push_back(entry.path());
    }
  }
  for (const fs::path& path : files) {
    std::ifstream file(path);
    std::vector<std::string> arguments;
    bool in_command = false;
    for (std::string line; std::getline(file, line);) {
      const bool start = line.rfind("#   smoothsteer tune", 0) == 0;
      if (!start && !(in_command && line.rfind("#     ", 0) == 0)) {
        if (in_command) break;
        continue;
      }
      in_command = true;
      std::istringstream words(line.substr(start ? 15 : 1));
      for (std::string word; words >> word;) arguments.push_back(word);
    }
    if (arguments.empty()) continue;
    SCOPED_TRACE(path.string());
    const auto out = std::find(arguments.begin(), arguments.end(), "--out");
    ASSERT_NE(out, arguments.end());
    const fs::path committed = source_dir() / *(out + 1);
    *(out + 1) = (directory_ / "regenerated.csv").string();
    arguments.insert(arguments.begin(), SMOOTHSTEER_CLI);
    const ProcessResult run = run_process(arguments, source_dir());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    std::ifstream a(committed, std::ios::binary),
        b(directory_ / "regenerated.csv", std::ios::binary);
    const std::string expected{std::istreambuf_iterator<char>(a), {}};
    const std::string actual{std::istreambuf_iterator<char>(b), {}};
    EXPECT_FALSE(expected.empty()) << committed;
    EXPECT_EQ(actual, expected) << committed;
    ++checked;
  }
  EXPECT_GE(checked, 4);
}

}  // namespace
}  // namespace smoothsteer::testing
