// The paper's figures are data (data/paper_figures.csv): they are found by table, case and
// quantity, and a malformed file gets an error that names the file and the line.

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "smoothsteer/evaluation/paper_figures.hpp"
#include "support/hang_watchdog.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer {
namespace {

using testing::source_file;

std::string write_temporary(const std::string& content) {
  const std::string file =
      (std::filesystem::temp_directory_path() / "smoothsteer_paper_figures_test.csv").string();
  std::ofstream(file) << content;
  return file;
}

TEST(PaperFigures, TheRepositoryFileHasTheTablesFigures) {
  const PaperFigures figures = PaperFigures::load(source_file("data/paper_figures.csv"));
  EXPECT_EQ(figures.size(), 12u);
  EXPECT_DOUBLE_EQ(*figures.find("roc_vx", "-0.6283", "hosm_m"), 3.00);
  EXPECT_DOUBLE_EQ(*figures.find("lane_change", "15.0", "proposed_max_e_m"), 0.39);
  EXPECT_FALSE(figures.find("lane_change", "12.0", "proposed_max_e_m"));
  EXPECT_EQ(figures.text("lane_change", "10.0", "proposed_max_e_m", 3), "0.012");
  EXPECT_EQ(figures.text("lane_change", "12.0", "proposed_max_e_m", 3), "");
}

TEST(PaperFigures, MalformedLinesNameTheFileAndLine) {
  const std::string header = "# comment\ntable,case,quantity,value,source\n";
  for (const auto& [body, expected] :
       {std::pair{std::string("roc_vx,0,optimal_m,abc,x\n"), std::string(": line 3: value 'abc'")},
        std::pair{std::string("roc_vx,0,optimal_m\n"), std::string(": line 3: expected 5")},
        std::pair{std::string("a,b,c,1,x\na,b,c,2,x\n"), std::string(": line 4: duplicate")}}) {
    const std::string file = write_temporary(header + body);
    try {
      PaperFigures::load(file);
      FAIL() << "expected an error for " << body;
    } catch (const std::runtime_error& error) {
      EXPECT_NE(std::string(error.what()).find(file + expected), std::string::npos) << error.what();
    }
  }
  EXPECT_THROW(PaperFigures::load(write_temporary("table,case\n")), std::runtime_error);
}

// `compare --paper-figures FILE` reads a regular file only, and at most
// max_paper_figures_file_bytes of it: a FIFO blocked the reader and /dev/zero read 4.2 GB.
TEST(PaperFigures, OnlyABoundedRegularFileIsRead) {
  const std::filesystem::path directory =
      std::filesystem::temp_directory_path() / "smoothsteer_paper_figures_hostile";
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  const std::string fifo = (directory / "fifo.csv").string();
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  const std::string large = (directory / "large.csv").string();
  {
    std::ofstream output(large);
    output << "table,case,quantity,value,source\n# "
           << std::string(max_paper_figures_file_bytes, 'x') << "\n";
  }
  const testing::HangWatchdog watchdog("reading a FIFO or /dev/zero as paper figures");
  for (const auto& [file, expected] :
       {std::pair{fifo, std::string("not a regular file")},
        std::pair{std::string("/dev/zero"), std::string("not a regular file")},
        std::pair{directory.string(), std::string("is a directory")},
        std::pair{large, std::string("is larger than 1048576")}}) {
    try {
      PaperFigures::load(file);
      FAIL() << "expected an error for " << file;
    } catch (const std::runtime_error& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.rfind(file + ": paper figures file", 0), 0u) << message;
      EXPECT_NE(message.find(expected), std::string::npos) << message;
    }
  }
  std::filesystem::remove_all(directory);
}

}  // namespace
}  // namespace smoothsteer
