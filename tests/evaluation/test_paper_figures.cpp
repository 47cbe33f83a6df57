// The paper's figures are data (data/paper_figures.csv): they are found by table, case and
// quantity, and a malformed file gets an error that names the file and the line.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "smoothsteer/evaluation/paper_figures.hpp"
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

}  // namespace
}  // namespace smoothsteer
