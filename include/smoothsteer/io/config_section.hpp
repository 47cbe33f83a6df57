#pragma once
//! \file config_section.hpp
//! Strict reading of one YAML mapping: every read names its key, checks type and range, and is
//! remembered, so that finish() can reject keys nobody read. Errors are ConfigError with the
//! message "<file>: key '<path.to.key>' (line L): <reason>". Each read value (or default) is
//! recorded in resolved(), which becomes the "parameters" of summary.json.

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <limits>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "smoothsteer/io/text_checks.hpp"
#include "smoothsteer/value_range.hpp"

namespace smoothsteer::io {

class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

//! Allowed interval of a number (value_range.hpp). Every number must also be finite with
//! magnitude <= max_input_magnitude (text_checks.hpp).
using Range = ValueRange;
//! "must be in [0, 1]", "must be > 0 and <= 1e+15": the range of a scenario key as its error
//! message states it, the magnitude cap included.
std::string describe(const Range& range);

class ConfigSection {
 public:
  //! `node` must be a mapping or null (= empty); `key_path` is "" for the root.
  ConfigSection(YAML::Node node, std::string key_path, std::string file);

  bool has(const std::string& key) const;
  double number(const std::string& key, double default_value, Range range = {});
  double required_number(const std::string& key, Range range = {});
  int integer(const std::string& key, int default_value, int min, int max);
  bool boolean(const std::string& key, bool default_value);
  std::string text(const std::string& key, const std::string& default_value,
                   const std::vector<std::string>& allowed = {});
  std::string required_text(const std::string& key);
  std::vector<double> numbers(const std::string& key, const std::vector<double>& default_value,
                              std::size_t min_count, std::size_t max_count, Range range = {});
  //! A nested mapping (empty if absent). Call finish() on it too; store() its resolved().
  ConfigSection section(const std::string& key);
  //! The raw node (marked as read); for lists of mappings.
  YAML::Node raw(const std::string& key);
  //! Records a resolved value that was read by other means.
  void store(const std::string& key, const YAML::Node& value);

  //! Throws ConfigError naming every key that was never read.
  void finish() const;
  [[noreturn]] void fail(const std::string& key, const std::string& reason) const;

  //! Key paths set by --set overrides: their errors say "(from --set)" instead of a line.
  void set_overridden_keys(std::shared_ptr<const std::set<std::string>> keys) {
    overridden_ = std::move(keys);
  }

  const YAML::Node& resolved() const { return resolved_; }
  const std::string& file() const { return file_; }
  std::string full_key(const std::string& key) const;

 private:
  YAML::Node node_;
  std::string key_path_;
  std::string file_;
  std::set<std::string> read_;
  YAML::Node resolved_;
  std::shared_ptr<const std::set<std::string>> overridden_;
};

//! Most nodes a YAML document may expand to, each alias counted once per use (a billion-laughs
//! file expands to 10^9). 1 000 000 inline waypoints are 3 000 001 nodes.
inline constexpr std::size_t max_yaml_nodes = 4'000'000;
//! Deepest nesting of mappings and lists in a YAML document.
inline constexpr std::size_t max_yaml_depth = 64;

//! Loads a YAML file (a regular file of at most max_yaml_file_bytes, bounded_file.hpp);
//! ConfigError "<file>: YAML file: cannot open file" / "... is a directory, not a regular file" /
//! "... is not a regular file" / "<file>: not valid UTF-8 at line L" / "<file>: malformed YAML at
//! line L, column C: <reason>" / "<file>: key 'a.b' (line L): duplicate key (first given at line
//! M)" / "<file>: key 'a.b' (line L): an alias refers to a node that contains it (a cycle)" /
//! "... the document expands to more than max_yaml_nodes nodes" / "... nested deeper than
//! max_yaml_depth levels".
YAML::Node load_yaml_file(const std::string& file);
//! The same checks on YAML text already in memory (`file` names it in messages).
YAML::Node parse_yaml_text(const std::string& text, const std::string& file);

}  // namespace smoothsteer::io
