#pragma once
//! \file results_table.hpp
//! A small text table written as CSV and as GitHub Markdown (docs/results/).

#include <string>
#include <vector>

namespace smoothsteer {

struct ResultsTable {
  std::string title;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> notes;  //!< lines printed under the Markdown table

  //! Fixed-point text of a number with `digits` decimals ("nan" stays "nan").
  static std::string number(double value, int digits = 3);
  std::string to_csv() const;
  std::string to_markdown() const;
  //! Writes <directory>/<stem>.csv and <stem>.md (creating the directory), each through a
  //! temporary file and a rename (io::write_file_atomically); throws
  //! std::runtime_error naming the file on failure.
  void write(const std::string& directory, const std::string& stem) const;
};

}  // namespace smoothsteer
