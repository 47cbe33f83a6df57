#include "smoothsteer/evaluation/results_table.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "smoothsteer/io/atomic_output.hpp"

namespace smoothsteer {

std::string ResultsTable::number(double value, int digits) {
  if (!std::isfinite(value)) return "nan";
  std::ostringstream text;
  text.setf(std::ios::fixed);
  text.precision(digits);
  text << value;
  return text.str();
}

std::string ResultsTable::to_csv() const {
  std::ostringstream text;
  auto line = [&](const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < cells.size(); ++i) text << (i ? "," : "") << cells[i];
    text << '\n';
  };
  line(header);
  for (const auto& row : rows) line(row);
  return text.str();
}

std::string ResultsTable::to_markdown() const {
  std::ostringstream text;
  if (!title.empty()) text << "### " << title << "\n\n";
  auto line = [&](const std::vector<std::string>& cells) {
    text << '|';
    for (const std::string& cell : cells) text << ' ' << cell << " |";
    text << '\n';
  };
  line(header);
  text << '|';
  for (std::size_t i = 0; i < header.size(); ++i) text << (i == 0 ? " --- |" : " ---: |");
  text << '\n';
  for (const auto& row : rows) line(row);
  if (!notes.empty()) text << '\n';
  for (const std::string& note : notes) text << note << '\n';
  return text.str();
}

void ResultsTable::write(const std::string& directory, const std::string& stem) const {
  std::filesystem::create_directories(directory);
  // Through a temporary file and a rename: an interrupted or failed run leaves the previous table.
  io::write_file_atomically(directory + "/" + stem + ".csv", to_csv(), "--out");
  io::write_file_atomically(directory + "/" + stem + ".md", to_markdown(), "--out");
}

}  // namespace smoothsteer
