// The hostile inputs that adversarial testing found, as one table. Every one must be
// rejected with a message that names the file (or option), the key or line, and the rule.

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "smoothsteer/io/atomic_output.hpp"
#include "smoothsteer/io/schedule_files.hpp"
#include "smoothsteer/io/text_checks.hpp"
#include "smoothsteer/io/waypoint_csv.hpp"
#include "smoothsteer/runner/scenario.hpp"
#include "smoothsteer/runner/sweep.hpp"
#include "support/counting_allocator.hpp"
#include "support/hang_watchdog.hpp"

namespace smoothsteer::runner {
namespace {

namespace fs = std::filesystem;

//! A rejected input allocates no more than this in one request. Refusals take 8 KiB at most
//! (a stream's buffer); what the inputs ask for is far more (a 17 MiB schedule, 1e17 m of lane
//! change sampled every few centimetres).
constexpr std::size_t max_rejection_allocation_bytes = 1u << 20;

constexpr const char* valid =
    "name: t\npath: {type: straight}\nspeed: {initial_mps: 5}\ncontroller: {type: lead_wheel}\n";

struct BadInput {
  const char* what;
  std::string scenario;                //!< text of s.yaml
  std::vector<std::string> overrides;  //!< --set
  std::vector<std::string> expected;   //!< parts of the message ("FILE" = the scenario path)
  //! Largest single allocation while it is refused; more than the default only where a legal
  //! object comes first (a 2e7 m path samples its curvature in 32 MB before the speed profile,
  //! which asked for 2.56 GB, is refused).
  std::size_t allocation_bytes = max_rejection_allocation_bytes;
};

class HostileInputs : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = fs::temp_directory_path() / ("smoothsteer_hostile_" + std::to_string(::getpid()));
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(directory_ / name, std::ios::binary) << text;
    return (directory_ / name).string();
  }
  std::string error_of(const BadInput& input) {
    const std::string file = write("s.yaml", input.scenario);
    try {
      load_scenario(file, input.overrides);
    } catch (const io::ConfigError& error) {
      return error.what();
    }
    return "";
  }
  fs::path directory_;
};

//! Nine lines, 9^9 nodes once the aliases are expanded. (Built by append: GCC 12 reports a
//! false -Wrestrict on chains of operator+.)
std::string billion_laughs_text() {
  std::string text = "a0: &a0 [x, x, x, x, x, x, x, x, x]\n";
  for (int level = 1; level < 9; ++level) {
    const std::string name = std::to_string(level);
    const std::string previous = std::to_string(level - 1);
    text.append("a").append(name).append(": &a").append(name).append(" [");
    for (int k = 0; k < 9; ++k) text.append(k ? ", *a" : "*a").append(previous);
    text.append("]\n");
  }
  return text;
}

//! 24 mappings of two aliases each: 2^24 leaves.
std::string alias_map_text() {
  std::string text = "m0: &m0 {a: 1, b: 1}\n";
  for (int level = 1; level < 24; ++level) {
    const std::string name = std::to_string(level);
    const std::string previous = std::to_string(level - 1);
    text.append("m").append(name).append(": &m").append(name);
    text.append(" {a: *m").append(previous).append(", b: *m").append(previous).append("}\n");
  }
  return text;
}

std::string schedule_scenario(const std::string& schedule) {
  return "name: t\npath: {type: straight}\nspeed: {initial_mps: 5}\n"
         "controller: {type: scheduled_lead_wheel, schedule: " +
         schedule + "}\n";
}

//! A shuttle of `changes` gear changes, 2 m each way.
std::string shuttle_text(int changes) {
  std::string text = "path:\n  type: segments\n  pieces:\n";
  for (int i = 0; i <= changes; ++i) {
    text.append("  - {gear: ").append(i % 2 ? "reverse" : "forward").append(", line_m: 2}\n");
  }
  return text.append(
      "speed: {profile: curvature, max_mps: 1, max_lateral_acceleration_mps2: "
      "1}\ncontroller: {type: lead_wheel}\n");
}

TEST_F(HostileInputs, EveryBadInputIsRejectedWithFileKeyAndRule) {
  const std::string billion_laughs = billion_laughs_text();
  const std::string alias_map = alias_map_text();
  write("pts_huge.csv", "x,y\n0,0\n104,1e300\n");
  write("pts_garbage.csv", "x,y\n0,0\n1,0.3garbage\n");
  fs::create_directories(directory_ / "a_directory");
  const std::string s = valid;
  const std::vector<BadInput> table{
      // Magnitudes that break the arithmetic.
      {"start 1e155 m away",
       s,
       {"start.x_m=1e155"},
       {"FILE", "'start.x_m'", "1e+155", "1000000000"}},
      {"start.x_m = 1e308", s, {"start.x_m=1e308"}, {"FILE", "'start.x_m'", "out of range"}},
      {"circle of radius 1e308",
       "path: {type: circle, radius_m: 1e308}\ncontroller: {type: lead_wheel}\n",
       {},
       {"FILE", "'path.radius_m'", "out of range"}},
      {"waypoint row 104,1e300",
       "path: {type: waypoints_csv, file: pts_huge.csv}\ncontroller: {type: lead_wheel}\n",
       {},
       {"pts_huge.csv", "line 3", "magnitude"}},
      {"overflowing number", s, {"start.y_m=1e999"}, {"'start.y_m'", "expected a number"}},
      // Counts the input controls.
      {"lane change from 1e17",
       "path: {type: lane_change}\ncontroller: {type: lead_wheel}\n",
       {"path.x_start_m=-1e8", "path.x_end_m=1e8", "path.spacing_m=0.05"},
       {"FILE", "'path.x_end_m'", "samples", "at most"}},
      {"curvature profile on a 2e7 m line",
       "path: {type: straight, length_m: 2e7}\n"
       "speed: {profile: curvature, max_mps: 10, max_lateral_acceleration_mps2: 2}\n"
       "controller: {type: lead_wheel}\n",
       {},
       {"FILE", "'speed.profile'", "2e+07 m long", "at most 1000000 grid points"},
       64u << 20},
      {"gear run of 1e8 m",
       "path: {type: segments, pieces: [{line_m: 5e7}, {gear: reverse, line_m: 5e7}]}\n"
       "speed: {profile: curvature, max_mps: 3, max_lateral_acceleration_mps2: 2}\n"
       "controller: {type: lead_wheel}\n",
       {},
       {"FILE", "'speed.profile'", "at most 1000000 grid points"},
       64u << 20},
      {"10 001 gear changes",
       shuttle_text(10001),
       {},
       {"FILE", "'path.pieces[10001].gear'", "max_cusps = 10000"}},
      {"a controller key below line 1",
       "name: t\npath: {type: straight}\nspeed: {initial_mps: 5}\n\n\ncontroller:\n"
       "  type: lead_wheel\n  k_rob: 1.5\n",
       {},
       {"FILE", "key 'controller.k_rob' (line 8)", "[0, 1)"}},
      {"lane change x_start 1e17",
       "path: {type: lane_change}\ncontroller: {type: lead_wheel}\n",
       {"path.x_start_m=1e17"},
       {"FILE", "'path.x_start_m'", "out of range"}},
      {"steering offset beyond a rack's misalignment",
       s,
       {"simulation.steering_offset_rad=0.5"},
       {"FILE", "'simulation.steering_offset_rad'", "0.5", "out of range", "[-0.1, 0.1]"}},
      {"steering offset NaN",
       s,
       {"simulation.steering_offset_rad=.nan"},
       {"FILE", "'simulation.steering_offset_rad'"}},
      {"tiny period, long run",
       s,
       {"simulation.substep_s=1e-6", "simulation.control_period_s=1e-5",
        "simulation.duration_s=3600"},
       {"FILE", "'simulation'", "duration_s", "control steps", "1e+07"}},
      // Silent acceptance.
      {"duplicate key",
       s + "name: again\n",
       {},
       {"FILE", "'name'", "line 5", "duplicate key", "line 1"}},
      {"nested duplicate key",
       "path: {type: straight, length_m: 3, length_m: 4}\ncontroller: {type: lead_wheel}\n",
       {},
       {"FILE", "'path.length_m'", "duplicate key"}},
      {"only a name", "name: x\n", {}, {"FILE", "'path'", "is required"}},
      {"unknown controller type",
       "path: {type: straight}\ncontroller: {type: pure_persuit}\n",
       {},
       {"FILE", "'controller.type'", "pure_persuit", "steering_system"}},
      {"tilde value",
       s + "simulation: {duration_s: ~}\n",
       {},
       {"FILE", "'simulation.duration_s'", "has no value"}},
      {"empty value",
       s + "simulation:\n  duration_s:\n",
       {},
       {"'simulation.duration_s'", "has no value"}},
      {"empty --set value",
       s,
       {"controller.k_rob="},
       {"'controller.k_rob'", "(from --set)", "has no value"}},
      {"0.3garbage",
       s,
       {"controller.k_rob=0.3garbage"},
       {"'controller.k_rob'", "expected a number", "0.3garbage"}},
      {"0.3garbage in a list",
       s,
       {"start={x_m: 1}", "path.start=[0, 0.3garbage]"},
       {"'path.start'", "element 1"}},
      {"garbage in a waypoint CSV",
       "path: {type: waypoints_csv, file: pts_garbage.csv}\ncontroller: {type: lead_wheel}\n",
       {},
       {"pts_garbage.csv", "line 3", "two finite numbers"}},
      {"unknown enum value",
       s,
       {"controller.surface=7"},
       {"'controller.surface'", "'7'", "must be one of"}},
      // Text must be UTF-8.
      {"non-UTF-8 description",
       s + "description: caf\xe9\n",
       {},
       {"FILE", "not valid UTF-8", "line 5"}},
      {"non-UTF-8 --set", s, {"name=caf\xe9"}, {"override", "not valid UTF-8"}},
      // Messages that named nothing.
      {"non-string vehicle.file",
       s + "vehicle: {file: [1, 2]}\n",
       {},
       {"FILE", "'vehicle.file'", "expected a string"}},
      {"vehicle.file ~",
       s + "vehicle: {file: ~}\n",
       {},
       {"FILE", "'vehicle.file'", "has no value"}},
      {"vehicle file is a directory",
       s + "vehicle: {file: a_directory}\n",
       {},
       {"a_directory", "is a directory"}},
      {"waypoint file is a directory",
       "path: {type: waypoints_csv, file: a_directory}\ncontroller: {type: lead_wheel}\n",
       {},
       {"a_directory", "not a regular file"}},
      {"control period not a multiple, shown exactly",
       s,
       {"simulation.control_period_s=0.0200001"},
       {"'simulation'", "0.0200001", "whole multiple"}},
      // A schedule whose middle row breaks a rule (it used to load and stop the run at step 0).
      {"schedule middle row k_rob = 5",
       "name: t\npath: {type: straight}\nspeed: {initial_mps: 5}\n"
       "controller: {type: scheduled_lead_wheel, schedule: sch_bad.csv}\n",
       {},
       {"sch_bad.csv", "line 3", "k_rob"}},
      {"waypoint file ~",
       "name: t\npath: {type: waypoints_csv, file: ~}\nspeed: {initial_mps: 5}\n"
       "controller: {type: lead_wheel}\n",
       {},
       {"FILE", "'path.file'", "has no value"}},
      // Aliases: a cycle used to overflow the stack, a billion laughs to run for minutes.
      {"alias cycle", s + "extra: &a [*a]\n", {}, {"FILE", "'extra[0]'", "line 5", "cycle"}},
      {"alias cycle in a mapping",
       s + "extra: &a {b: *a}\n",
       {},
       {"FILE", "'extra.b'", "line 5", "cycle"}},
      {"billion laughs", s + billion_laughs, {}, {"FILE", "expands to more than", "4000000"}},
      {"2^24-entry alias map", s + alias_map, {}, {"FILE", "expands to more than", "4000000"}},
      {"nested 100 deep",
       s + "deep: " + std::string(100, '[') + std::string(100, ']') + "\n",
       {},
       {"FILE", "nested deeper than 64"}},
      {"alias cycle from --set", s, {"start=&a [*a]"}, {"override", "cycle"}},
      // Files that are not regular files, or too large, given as the schedule.
      {"schedule /dev/zero",
       schedule_scenario("/dev/zero"),
       {},
       {"FILE", "'controller.schedule'", "/dev/zero", "not a regular file"}},
      {"schedule FIFO",
       schedule_scenario("fifo.csv"),
       {},
       {"FILE", "'controller.schedule'", "fifo.csv", "not a regular file"}},
      {"schedule of 17 MiB",
       schedule_scenario("huge.csv"),
       {},
       {"FILE", "'controller.schedule'", "huge.csv", "larger than 16777216 bytes"}},
      {"schedule is a directory",
       schedule_scenario("a_directory"),
       {},
       {"'controller.schedule'", "is a directory"}},
      // Library values that overflowed a float-to-int conversion.
      {"max_substep_fraction 1e-308",
       s,
       {"controller.max_substep_fraction=1e-308"},
       {"FILE", "'controller'", "max_substep_fraction = 1e-308", "min_substep_m"}},
      {"lead_wheelbase_m 1e-308",
       s,
       {"controller.lead_wheelbase_m=1e-308"},
       {"FILE", "'controller'", "wheelbases_m[1] (lambda_2) = 1e-308", "[0.01, 100]"}},
      {"wheelbases_m [1e-308, 1]",
       s,
       {"controller.wheelbases_m=[1e-308, 1]"},
       {"FILE", "'controller.wheelbases_m'", "element 0 = 1e-308", "[0.01, 100]"}},
      // A path that doubles back on itself.
      {"waypoint CSV 0 -> 30 -> 0",
       "path: {type: waypoints_csv, file: pts_back.csv}\ncontroller: {type: lead_wheel}\n",
       {},
       {"FILE", "'path.file'", "pts_back.csv", "line 4", "turns back on itself"}},
      {"inline waypoints 0 -> 30 -> 0",
       "path: {type: waypoints, points: [[0, 0], [30, 0], [0, 0.5]]}\n"
       "controller: {type: lead_wheel}\n",
       {},
       {"FILE", "'path.points'", "element 1", "turns back on itself"}},
      // Values that collapse the adaptive plant steps.
      {"mass 1e9 kg",
       s,
       {"vehicle.mass_kg=1e9"},
       {"FILE", "'vehicle.mass_kg'", "(from --set)", "mass_kg = 1e+09", "[1, 1e6] kg"}},
      {"yaw inertia 0.01",
       s,
       {"vehicle.yaw_inertia_kgm2=0.01"},
       {"'vehicle.yaw_inertia_kgm2'", "(from --set)", "dynamic index", "[0.1, 10]"}},
      {"Pacejka B 1e6",
       s,
       {"vehicle.front_tire.stiffness_factor_b=1e6"},
       {"'vehicle.front_tire.stiffness_factor_b'", "(from --set)", "<= 100"}},
      // A path key given a number names the key.
      {"vehicle.file a number",
       s + "vehicle: {file: 0.0}\n",
       {},
       {"FILE", "'vehicle.file'", "line 5", "0.0", "no such file"}},
      {"path.file a number",
       "path: {type: waypoints_csv, file: 0.0}\ncontroller: {type: lead_wheel}\n",
       {},
       {"FILE", "'path.file'", "line 1", "0.0", "no such file"}},
  };
  ASSERT_EQ(::mkfifo((directory_ / "fifo.csv").c_str(), 0600), 0);
  std::ofstream(directory_ / "huge.csv").close();
  fs::resize_file(directory_ / "huge.csv", (16u << 20) + 1);
  write("pts_back.csv", "x,y\n0,0\n# the turn\n30,0\n0,0\n");
  write("sch_bad.csv",
        "speed_mps,region,fictive_wheelbase_m,lead_wheelbase_m,lead_curvature_bound_per_m,"
        "lead_radius_m,k_rob,max_steering_angle_rad,max_steering_rate_radps,"
        "max_steering_acceleration_radps2,feedforward_curvature_bound_per_m,"
        "feedforward_curvature_rate_per_m2\n"
        "1,5,2.57,0.1,0.1,10,0.3,0.25,0.4,4,0.02,0.01\n"
        "2,5,2.57,0.1,0.08,12.5,5,0.2,0.4,5,0.02,0.01\n"
        "3,5,2.57,0.1,0.05,20,0.3,0.13,0.4,7,0.02,0.01\n");
  const std::string file = (directory_ / "s.yaml").string();
  for (const BadInput& input : table) {
    SCOPED_TRACE(input.what);
    largest_allocation_bytes = 0;
    const testing::HangWatchdog watchdog(input.what);  // the lane change from 1e17 used to spin
    const std::string message = error_of(input);
    ASSERT_FALSE(message.empty()) << "accepted: " << input.what;
    for (const std::string& part : input.expected) {
      const std::string wanted = part == "FILE" ? file : part;
      EXPECT_NE(message.find(wanted), std::string::npos)
          << "'" << wanted << "' missing in: " << message;
    }
    // Rejected before any large allocation: the largest single request stays far below what
    // the input asked for (a 17 MiB schedule, 1e17 m of lane change, 1e9 kg).
    EXPECT_LT(largest_allocation_bytes.load(), input.allocation_bytes);
  }
}

// Anchors and aliases within the caps are YAML as usual; a shared list counts once per use.
TEST_F(HostileInputs, AliasesWithinTheCapsLoad) {
  const std::string file = write("s.yaml",
                                 "name: t\nspeed: {initial_mps: &v 5, final_mps: *v}\n"
                                 "path: {type: waypoints, points: [&p [0, 0], [10, 0], [20, 2]]}\n"
                                 "start: {x_m: &x 1, y_m: *x}\ncontroller: {type: lead_wheel}\n");
  const Scenario scenario = load_scenario(file);
  EXPECT_EQ(scenario.start.position.y, 1.0);
  EXPECT_EQ(scenario.speed.final_speed_mps, 5.0);
  // 8^7 = 2 097 152 nodes: under the cap of 4 000 000, and checked without walking them all.
  std::string text = "l0: &l0 [0, 0, 0, 0, 0, 0, 0, 0]\n";
  for (int level = 1; level < 7; ++level) {
    const std::string name = std::to_string(level);
    const std::string previous = std::to_string(level - 1);
    text.append("l").append(name).append(": &l").append(name).append(" [");
    for (int k = 0; k < 8; ++k) text.append(k ? ", *l" : "*l").append(previous);
    text.append("]\n");
  }
  {
    // Checked without walking the 2 million nodes: a walk would take minutes under ASan.
    const testing::HangWatchdog watchdog("8^7 shared nodes");
    EXPECT_NO_THROW(io::parse_yaml_text(text, "shared.yaml"));
  }
  EXPECT_THROW(io::parse_yaml_text(text + "l7: [*l6, *l6]\n", "shared.yaml"), io::ConfigError);
}

TEST_F(HostileInputs, SubnormalNumbersAreNumbers) {
  const std::string file = write("s.yaml", valid);
  EXPECT_NO_THROW(load_scenario(file, {"start.heading_rad=1e-308", "start.y_m=4.9e-324"}));
  EXPECT_EQ(io::parse_number("1e-308"), 1e-308);
  EXPECT_FALSE(io::parse_number("1e309"));
  EXPECT_FALSE(io::parse_number("0.3garbage"));
  EXPECT_FALSE(io::parse_number(" 1"));
  EXPECT_FALSE(io::parse_number("nan"));
  EXPECT_FALSE(io::parse_number("inf"));
  EXPECT_FALSE(io::parse_number(""));
  EXPECT_EQ(io::parse_number("-2.5e3"), -2500.0);
}

TEST_F(HostileInputs, Utf8Validation) {
  EXPECT_FALSE(io::invalid_utf8_offset("plain ascii, caf\xc3\xa9, \xe2\x82\xac, \xf0\x9f\x9a\x97"));
  EXPECT_EQ(io::invalid_utf8_offset("ab\xe9"), 2u);            // Latin-1 byte
  EXPECT_EQ(io::invalid_utf8_offset("\xc0\xaf"), 0u);          // overlong '/'
  EXPECT_EQ(io::invalid_utf8_offset("x\xed\xa0\x80"), 1u);     // surrogate
  EXPECT_EQ(io::invalid_utf8_offset("\xf4\x90\x80\x80"), 0u);  // above U+10FFFF
  EXPECT_EQ(io::invalid_utf8_offset("\xe2\x82"), 0u);          // truncated
}

TEST_F(HostileInputs, SweepGridIsCountedBeforeItIsBuilt) {
  std::vector<SweepAxis> axes(30, SweepAxis{"controller.k_rob", {"0.2", "0.3"}});
  try {
    sweep_grid(axes);
    FAIL() << "a 2^30-row grid was accepted";
  } catch (const io::ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("--vary"), std::string::npos) << error.what();
  }
  axes.resize(3);
  EXPECT_EQ(sweep_grid(axes).size(), 8u);
}

TEST_F(HostileInputs, AtomicOutputsRefuseWhatTheyMustNotReplace) {
  const fs::path fifo = directory_ / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_THROW(io::write_file_atomically(fifo.string(), "x", "--out"), std::runtime_error);
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_THROW(io::OutputDirectory(fifo.string(), "--out"), std::runtime_error);
  EXPECT_THROW(io::OutputDirectory(directory_.string() + "/.", "--out"), std::runtime_error);

  const fs::path target = directory_ / "run";
  {
    io::OutputDirectory out(target.string(), "--out");
    std::ofstream(out.file("trace.csv")) << "old";
    out.commit();
  }
  {
    io::OutputDirectory out(target.string(), "--out");
    std::ofstream(out.file("trace.csv")) << "new";
    // not committed: destroyed on the way out of a failing run
  }
  EXPECT_EQ(std::ifstream(target / "trace.csv").rdbuf()->sgetc(), 'o');
  {
    io::OutputDirectory out(target.string(), "--out");
    std::ofstream(out.file("summary.json")) << "{}";
    out.commit();
  }
  EXPECT_FALSE(fs::exists(target / "trace.csv")) << "the old set must be replaced as a whole";
  EXPECT_TRUE(fs::exists(target / "summary.json"));
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(directory_)) ++entries;
  EXPECT_EQ(entries, 2u) << "temporary directories left behind";
}

// NAME_MAX is 255: a legal output name of 236-255 bytes used to fail on its temporary name.
TEST_F(HostileInputs, OutputsWithTheLongestLegalNameArePublished) {
  const fs::path directory = directory_ / std::string(255, 'd');
  for (int round = 0; round < 2; ++round) {  // new, then replacing the previous outputs
    io::OutputDirectory out(directory.string(), "--out");
    std::ofstream(out.file("trace.csv")) << "t\n";
    ASSERT_NO_THROW(out.commit());
  }
  EXPECT_TRUE(fs::exists(directory / "trace.csv"));
  const fs::path file = directory_ / std::string(255, 'f');
  ASSERT_NO_THROW(io::write_file_atomically(file.string(), "speed_mps\n", "--out"));
  ASSERT_NO_THROW(io::write_file_atomically(file.string(), "speed_mps\n", "--out"));
  EXPECT_EQ(fs::file_size(file), 10u);
}

// The tuner's vehicle reader: the loader's checks and the simulation schema's rules.
TEST_F(HostileInputs, TunerVehicleReaderRefusesWhatRunRefuses) {
  const std::string limits =
      "max_steering_angle_rad: 0.5\nmax_steering_rate_radps: 0.4\nwheelbase_m: 2.7\n";
  const auto message = [](const std::string& file) {
    try {
      io::load_vehicle_limits(file);
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  const auto expect = [&](const std::string& file, std::initializer_list<const char*> parts) {
    const std::string text = message(file);
    ASSERT_FALSE(text.empty()) << file << " accepted";
    for (const char* part : parts) {
      EXPECT_NE(text.find(part), std::string::npos) << "'" << part << "' missing in: " << text;
    }
    EXPECT_EQ(text.find("yaml-cpp"), std::string::npos) << text;
  };
  EXPECT_EQ(message(write("ok.yaml", limits)), "");
  expect(write("key.yaml", limits + "[a, b]: 1\n"), {"key.yaml", "line 4", "plain strings"});
  expect(write("nan.yaml", limits + "front_tire: {stiffness_factor_b: .nan}\n"),
         {"nan.yaml", "'front_tire.stiffness_factor_b'", ".nan"});
  expect(write("mass.yaml", limits + "mass_kg: 1e9\n"), {"mass.yaml", "'mass_kg'", "[1, 1e6]"});
  expect(write("rate.yaml", limits + "max_steering_acceleration_radps2: .inf\n"),
         {"rate.yaml", "max_steering_acceleration_radps2", ".inf"});
  fs::create_directories(directory_ / "dir.yaml");
  expect((directory_ / "dir.yaml").string(), {"dir.yaml", "is a directory"});
  const fs::path fifo = directory_ / "fifo.yaml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expect(fifo.string(), {"fifo.yaml", "not a regular file"});
  expect("/dev/zero", {"/dev/zero", "not a regular file"});
  expect(write("cycle.yaml", limits + "name: &a [*a]\n"), {"cycle.yaml", "cycle"});
}

TEST_F(HostileInputs, WaypointCsvReader) {
  EXPECT_EQ(io::parse_waypoint_csv("x,y\n# c\n0,0\n\n1, 2\r\n", "w.csv").size(), 2u);
  EXPECT_THROW(io::parse_waypoint_csv("0,0\n1,2,3\n", "w.csv"), io::ConfigError);
  EXPECT_THROW(io::parse_waypoint_csv("0,0\n", "w.csv"), io::ConfigError);
  EXPECT_THROW(io::parse_waypoint_csv("0,0\n1,inf\n", "w.csv"), io::ConfigError);
  EXPECT_THROW(io::parse_waypoint_csv("0,0\n30,0\n0,0\n", "w.csv"), io::ConfigError);
  EXPECT_EQ(io::parse_waypoint_csv("0,0\n30,0\n30,40\n", "w.csv").size(), 3u);  // a right angle
}

}  // namespace
}  // namespace smoothsteer::runner
