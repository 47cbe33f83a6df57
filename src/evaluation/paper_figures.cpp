#include "smoothsteer/evaluation/paper_figures.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "smoothsteer/evaluation/results_table.hpp"
#include "smoothsteer/io/bounded_file.hpp"

namespace smoothsteer {

namespace {

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ',')) fields.push_back(field);
  return fields;
}

}  // namespace

PaperFigures PaperFigures::load(const std::string& file) {
  // Regular files only, bounded: a FIFO blocked the reader and /dev/zero read 4.2 GB.
  std::istringstream input(
      io::read_bounded_file(file, max_paper_figures_file_bytes, "paper figures file"));
  PaperFigures figures;
  std::string line;
  bool header_seen = false;
  for (int number = 1; std::getline(input, line); ++number) {
    if (line.empty() || line[0] == '#') continue;
    const auto fail = [&](const std::string& reason) {
      throw std::runtime_error(file + ": line " + std::to_string(number) + ": " + reason);
    };
    const std::vector<std::string> fields = split_fields(line);
    if (!header_seen) {
      if (line != "table,case,quantity,value,source") {
        fail("expected the header 'table,case,quantity,value,source'");
      }
      header_seen = true;
      continue;
    }
    if (fields.size() != 5)
      fail("expected 5 comma-separated fields, got " + std::to_string(fields.size()));
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(fields[3], &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != fields[3].size() || !std::isfinite(value)) {
      fail("value '" + fields[3] + "' is not a finite number");
    }
    if (!figures.values_.emplace(std::tuple{fields[0], fields[1], fields[2]}, value).second) {
      fail("duplicate figure " + fields[0] + "/" + fields[1] + "/" + fields[2]);
    }
  }
  if (!header_seen) throw std::runtime_error(file + ": no header line");
  return figures;
}

std::optional<double> PaperFigures::find(std::string_view table, std::string_view case_key,
                                         std::string_view quantity) const {
  const auto found =
      values_.find(std::tuple{std::string(table), std::string(case_key), std::string(quantity)});
  if (found == values_.end()) return std::nullopt;
  return found->second;
}

std::string PaperFigures::text(std::string_view table, std::string_view case_key,
                               std::string_view quantity, int digits) const {
  const std::optional<double> value = find(table, case_key, quantity);
  return value ? ResultsTable::number(*value, digits) : "";
}

}  // namespace smoothsteer
