#pragma once
//! \file paper_figures.hpp
//! The paper's published figures, kept as data (data/paper_figures.csv) rather than in code, so
//! that the comparison tables can show them next to the measured values.
//!
//! File format: '#' comment lines, a header `table,case,quantity,value,source`, then one figure
//! per line. `case` is the row key exactly as the table prints it (e.g. "10.0" for a speed).

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>

namespace smoothsteer {

//! Largest paper figures file read [bytes]; the shipped one is about 1 kB.
inline constexpr std::uintmax_t max_paper_figures_file_bytes = 1u << 20;

class PaperFigures {
 public:
  //! No figures: tables leave the paper columns empty.
  PaperFigures() = default;
  //! Throws std::runtime_error "<file>: line L: <reason>" for a malformed file, a duplicate
  //! figure or a non-numeric value, and io::FileReadError "<file>: paper figures file ..." if it
  //! cannot be read, is not a regular file (a FIFO, a device) or is larger than
  //! max_paper_figures_file_bytes.
  static PaperFigures load(const std::string& file);

  std::optional<double> find(std::string_view table, std::string_view case_key,
                             std::string_view quantity) const;
  //! The figure as table text with `digits` decimals, or "" if the paper has none.
  std::string text(std::string_view table, std::string_view case_key, std::string_view quantity,
                   int digits) const;
  std::size_t size() const noexcept { return values_.size(); }

 private:
  std::map<std::tuple<std::string, std::string, std::string>, double, std::less<>> values_;
};

}  // namespace smoothsteer
