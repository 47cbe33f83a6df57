#include "smoothsteer/io/config_section.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "smoothsteer/io/text_checks.hpp"

namespace smoothsteer::io {
namespace {

std::string format_number(double x) {
  std::ostringstream out;
  out.precision(10);
  out << x;
  return out.str();
}

std::string show(const YAML::Node& node) {
  if (node.IsScalar()) return "'" + node.Scalar() + "'";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a mapping";
  return "nothing";
}

}  // namespace

bool Range::contains(double x) const {
  if (!std::isfinite(x) || std::abs(x) > max_input_magnitude) return false;
  const bool above = min_open ? x > min : x >= min;
  const bool below = max_open ? x < max : x <= max;
  return above && below;
}

std::string Range::describe() const {
  const bool has_min = std::isfinite(min), has_max = std::isfinite(max);
  if (has_min && has_max) {
    return std::string("must be in ") + (min_open ? "(" : "[") + format_number(min) + ", " +
           format_number(max) + (max_open ? ")" : "]");
  }
  const std::string cap = format_number(max_input_magnitude);
  if (has_min) {
    return std::string("must be ") + (min_open ? "> " : ">= ") + format_number(min) +
           " and <= " + cap;
  }
  if (has_max) {
    return std::string("must be ") + (max_open ? "< " : "<= ") + format_number(max) + " and >= -" +
           cap;
  }
  return "must be finite with magnitude <= " + cap;
}

ConfigSection::ConfigSection(YAML::Node node, std::string key_path, std::string file)
    : node_(node),
      key_path_(std::move(key_path)),
      file_(std::move(file)),
      resolved_(YAML::NodeType::Map) {
  if (node_ && !node_.IsNull() && !node_.IsMap()) {
    throw ConfigError(file_ + ": key '" + (key_path_.empty() ? "<root>" : key_path_) +
                      "': expected a mapping, got " + show(node_));
  }
}

std::string ConfigSection::full_key(const std::string& key) const {
  if (key.empty()) return key_path_;
  return key_path_.empty() ? key : key_path_ + "." + key;
}

void ConfigSection::fail(const std::string& key, const std::string& reason) const {
  std::string where;
  if (overridden_ && overridden_->count(full_key(key))) {
    where = " (from --set)";
  } else if (node_ && node_.IsMap() && node_[key] && node_[key].Mark().line >= 0) {
    where = " (line " + std::to_string(node_[key].Mark().line + 1) + ")";
  }
  throw ConfigError(file_ + ": key '" + full_key(key) + "'" + where + ": " + reason);
}

bool ConfigSection::has(const std::string& key) const {
  if (!node_ || !node_.IsMap() || !node_[key]) return false;
  // "key: ~" or "key:" used to mean the default silently (issue 12, defect 6).
  if (node_[key].IsNull()) fail(key, "has no value (~ or empty); give a value or remove the key");
  return true;
}

double ConfigSection::required_number(const std::string& key, Range range) {
  if (!has(key)) fail(key, "is required");
  return number(key, 0.0, range);
}

double ConfigSection::number(const std::string& key, double default_value, Range range) {
  read_.insert(key);
  double value = default_value;
  if (has(key)) {
    const YAML::Node n = node_[key];
    if (!n.IsScalar()) fail(key, "expected a number, got " + show(n));
    const std::optional<double> parsed = parse_number(n.Scalar());
    if (!parsed) fail(key, "expected a number, got '" + n.Scalar() + "'");
    value = *parsed;
  }
  if (!range.contains(value))
    fail(key, "value " + format_number(value) + " out of range: " + range.describe());
  resolved_[key] = value;
  return value;
}

int ConfigSection::integer(const std::string& key, int default_value, int min, int max) {
  read_.insert(key);
  int value = default_value;
  if (has(key)) {
    const YAML::Node n = node_[key];
    if (!n.IsScalar()) fail(key, "expected an integer, got " + show(n));
    const std::string& text = n.Scalar();
    std::size_t used = 0;
    try {
      value = std::stoi(text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != text.size() || text.empty()) fail(key, "expected an integer, got '" + text + "'");
  }
  if (value < min || value > max) {
    fail(key, "value " + std::to_string(value) + " out of range: must be in [" +
                  std::to_string(min) + ", " + std::to_string(max) + "]");
  }
  resolved_[key] = value;
  return value;
}

bool ConfigSection::boolean(const std::string& key, bool default_value) {
  read_.insert(key);
  bool value = default_value;
  if (has(key)) {
    const YAML::Node n = node_[key];
    if (!n.IsScalar() || !YAML::convert<bool>::decode(n, value)) {
      fail(key, "expected true or false, got " + show(n));
    }
  }
  resolved_[key] = value;
  return value;
}

std::string ConfigSection::text(const std::string& key, const std::string& default_value,
                                const std::vector<std::string>& allowed) {
  read_.insert(key);
  std::string value = default_value;
  if (has(key)) {
    const YAML::Node n = node_[key];
    if (!n.IsScalar()) fail(key, "expected a string, got " + show(n));
    value = n.Scalar();
  }
  if (!allowed.empty()) {
    bool ok = false;
    std::string list;
    for (const std::string& a : allowed) {
      ok = ok || a == value;
      list += (list.empty() ? "" : ", ") + a;
    }
    if (!ok) fail(key, "unknown value '" + value + "': must be one of " + list);
  }
  resolved_[key] = value;
  return value;
}

std::string ConfigSection::required_text(const std::string& key) {
  if (!has(key)) fail(key, "is required");
  return text(key, "");
}

std::vector<double> ConfigSection::numbers(const std::string& key,
                                           const std::vector<double>& default_value,
                                           std::size_t min_count, std::size_t max_count,
                                           Range range) {
  read_.insert(key);
  std::vector<double> values = default_value;
  if (has(key)) {
    const YAML::Node n = node_[key];
    if (!n.IsSequence()) fail(key, "expected a list of numbers, got " + show(n));
    values.clear();
    for (std::size_t i = 0; i < n.size(); ++i) {
      const std::optional<double> parsed =
          n[i].IsScalar() ? parse_number(n[i].Scalar()) : std::nullopt;
      if (!parsed) {
        fail(key, "element " + std::to_string(i) + ": expected a number, got " + show(n[i]));
      }
      const double x = *parsed;
      if (!range.contains(x)) {
        fail(key, "element " + std::to_string(i) + " = " + format_number(x) +
                      " out of range: " + range.describe());
      }
      values.push_back(x);
    }
  }
  if (values.size() < min_count || values.size() > max_count) {
    fail(key, "expected " + std::to_string(min_count) + ".." + std::to_string(max_count) +
                  " numbers, got " + std::to_string(values.size()));
  }
  YAML::Node list(YAML::NodeType::Sequence);
  for (double x : values) list.push_back(x);
  resolved_[key] = list;
  return values;
}

ConfigSection ConfigSection::section(const std::string& key) {
  read_.insert(key);
  ConfigSection child(has(key) ? node_[key] : YAML::Node(), full_key(key), file_);
  child.overridden_ = overridden_;
  return child;
}

YAML::Node ConfigSection::raw(const std::string& key) {
  read_.insert(key);
  return has(key) ? node_[key] : YAML::Node();
}

void ConfigSection::store(const std::string& key, const YAML::Node& value) {
  read_.insert(key);
  resolved_[key] = value;
}

void ConfigSection::finish() const {
  if (!node_ || !node_.IsMap()) return;
  std::string unknown;
  for (const auto& entry : node_) {
    const std::string key = entry.first.as<std::string>();
    if (!read_.count(key)) unknown += (unknown.empty() ? "'" : ", '") + full_key(key) + "'";
  }
  if (!unknown.empty()) {
    std::string known;
    for (const std::string& k : read_) known += (known.empty() ? "" : ", ") + k;
    throw ConfigError(file_ + ": unknown key " + unknown + " (known keys here: " + known + ")");
  }
}

namespace {

//! Largest YAML file read [bytes]; scenario and vehicle files are a few kB.
constexpr std::uintmax_t max_yaml_file_bytes = 16u << 20;

std::string key_text(const YAML::Node& key) {
  return key.IsScalar() ? key.Scalar() : std::string("<non-scalar key>");
}

//! yaml-cpp keeps duplicate keys and returns the first on lookup; reject them, and keys that
//! are not plain strings.
void reject_duplicate_keys(const YAML::Node& node, const std::string& path,
                           const std::string& file) {
  if (node.IsMap()) {
    std::map<std::string, int> lines;
    for (const auto& entry : node) {
      const std::string key = key_text(entry.first);
      const std::string full = path.empty() ? key : path + "." + key;
      const int line = entry.first.Mark().line + 1;
      if (!entry.first.IsScalar()) {
        throw ConfigError(file + ": key '" + full + "' (line " + std::to_string(line) +
                          "): keys must be plain strings");
      }
      const auto [previous, inserted] = lines.emplace(key, line);
      if (!inserted) {
        throw ConfigError(file + ": key '" + full + "' (line " + std::to_string(line) +
                          "): duplicate key (first given at line " +
                          std::to_string(previous->second) + ")");
      }
      reject_duplicate_keys(entry.second, full, file);
    }
  } else if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i) {
      reject_duplicate_keys(node[i], path + "[" + std::to_string(i) + "]", file);
    }
  }
}

}  // namespace

YAML::Node load_yaml_file(const std::string& file) {
  std::error_code error;
  const auto status = std::filesystem::status(file, error);
  if (!std::filesystem::exists(status))
    throw ConfigError(file + ": cannot open file (no such file)");
  if (std::filesystem::is_directory(status)) {
    throw ConfigError(file + ": is a directory, expected a YAML file");
  }
  if (!std::filesystem::is_regular_file(status)) {
    throw ConfigError(file + ": not a regular file, expected a YAML file");
  }
  if (std::filesystem::file_size(file, error) > max_yaml_file_bytes) {
    throw ConfigError(file + ": larger than " + std::to_string(max_yaml_file_bytes) +
                      " bytes; not a scenario or vehicle file");
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw ConfigError(file + ": cannot open file");
  std::ostringstream content;
  content << in.rdbuf();
  const std::string text = content.str();
  return parse_yaml_text(text, file);
}

YAML::Node parse_yaml_text(const std::string& text, const std::string& file) {
  try {
    require_utf8(text, file);
  } catch (const std::runtime_error& error) {
    throw ConfigError(error.what());
  }
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& error) {
    throw ConfigError(file + ": malformed YAML at line " + std::to_string(error.mark.line + 1) +
                      ", column " + std::to_string(error.mark.column + 1) + ": " + error.msg);
  }
  reject_duplicate_keys(root, "", file);
  return root;
}

}  // namespace smoothsteer::io
