#include "smoothsteer/io/config_section.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string_view>
#include <vector>

#include "smoothsteer/io/bounded_file.hpp"
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

//! A scenario key's number: finite, within the magnitude cap and in `range`.
bool accepts(const Range& range, double x) {
  return std::isfinite(x) && std::abs(x) <= max_input_magnitude && range.contains(x);
}

}  // namespace

std::string describe(const Range& range) {
  const auto [min, max, min_open, max_open] = range;
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
  // "key: ~" or "key:" used to mean the default silently (silent defaults hide typos).
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
  if (!accepts(range, value))
    fail(key, "value " + format_number(value) + " out of range: " + describe(range));
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
      if (!accepts(range, x)) {
        fail(key, "element " + std::to_string(i) + " = " + format_number(x) +
                      " out of range: " + describe(range));
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

//! One walk over a parsed document. yaml-cpp resolves an alias to the very node its anchor
//! names, so the document is a graph: `a: &a [*a]` is a cycle and nine nested lists of nine
//! aliases ("billion laughs") expand to 10^9 nodes. The walk checks every distinct container
//! once and counts what every later reader would visit, each alias once per use: it stops at a
//! cycle, beyond max_yaml_depth and beyond max_yaml_nodes, in time linear in the text.
struct DocumentWalk {
  //! One step from a container to a child: a key of a mapping or an index of a list.
  struct Step {
    const std::string* key;  //!< null for a list element
    std::size_t index;
  };
  //! What a container expands to: its nodes, itself included, and its nesting height.
  struct Expansion {
    std::size_t nodes = 1;
    std::size_t height = 0;
  };
  const std::string& file;
  std::size_t visited = 0;
  std::vector<YAML::Node> open;  //!< the containers from the root down to the current node
  std::vector<Step> steps;       //!< the way there; a key path is only built for a message
  //! Containers already walked, by where their text starts (no two containers of a parsed
  //! document start at the same place and are of the same type, but a non-scalar key, which
  //! the walk refuses before it looks inside).
  std::map<std::pair<int, int>, Expansion> walked;

  std::string path() const {
    std::string text;
    for (const Step& step : steps) {
      if (step.key) {
        text.append(text.empty() ? "" : ".").append(*step.key);
      } else {
        text.append("[").append(std::to_string(step.index)).append("]");
      }
    }
    return text.empty() ? "<root>" : text;
  }

  [[noreturn]] void fail(int line, const std::string& reason) const {
    throw ConfigError(file + ": key '" + path() + "' (line " + std::to_string(line) +
                      "): " + reason);
  }

  void count(std::size_t nodes, std::size_t height, int line) {
    visited += nodes;
    if (visited > max_yaml_nodes) {
      fail(line, "the document expands to more than " + std::to_string(max_yaml_nodes) +
                     " nodes (aliases count once per use); not a scenario or vehicle file");
    }
    if (open.size() + height > max_yaml_depth) {
      fail(line, "nested deeper than " + std::to_string(max_yaml_depth) + " levels");
    }
  }

  //! yaml-cpp keeps duplicate keys and returns the first on lookup; reject them, and keys that
  //! are not plain strings.
  Expansion walk(const YAML::Node& node) {
    const int line = node.Mark().line + 1;
    if (!node.IsMap() && !node.IsSequence()) {
      count(1, 0, line);
      return {};
    }
    for (const YAML::Node& outer : open) {
      if (outer.is(node)) fail(line, "an alias refers to a node that contains it (a cycle)");
    }
    const std::pair<int, int> where{node.Mark().pos, static_cast<int>(node.Type())};
    if (where.first >= 0) {
      if (const auto done = walked.find(where); done != walked.end()) {
        count(done->second.nodes, done->second.height, line);
        return done->second;
      }
    }
    count(1, 1, line);
    Expansion expansion{1, 1};
    const auto add = [&expansion](const Expansion& child) {
      expansion.nodes += child.nodes;
      expansion.height = std::max(expansion.height, child.height + 1);
    };
    open.push_back(node);
    if (node.IsMap()) {
      std::map<std::string_view, int> lines;
      for (const auto& entry : node) {
        const int key_line = entry.first.Mark().line + 1;
        static const std::string non_scalar = "<non-scalar key>";
        steps.push_back({entry.first.IsScalar() ? &entry.first.Scalar() : &non_scalar, 0});
        if (!entry.first.IsScalar()) fail(key_line, "keys must be plain strings");
        const auto [previous, inserted] = lines.emplace(entry.first.Scalar(), key_line);
        if (!inserted) {
          fail(key_line,
               "duplicate key (first given at line " + std::to_string(previous->second) + ")");
        }
        count(1, 0, key_line);  // the key itself
        ++expansion.nodes;
        add(walk(entry.second));
        steps.pop_back();
      }
    } else {
      for (std::size_t i = 0; i < node.size(); ++i) {
        steps.push_back({nullptr, i});
        add(walk(node[i]));
        steps.pop_back();
      }
    }
    open.pop_back();
    if (where.first >= 0) walked.emplace(where, expansion);
    return expansion;
  }
};

}  // namespace

YAML::Node load_yaml_file(const std::string& file) {
  std::string text;
  try {
    text = read_bounded_file(file, max_yaml_file_bytes, "YAML file");
  } catch (const FileReadError& error) {
    throw ConfigError(error.what());
  }
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
  DocumentWalk walk{file, 0, {}, {}, {}};
  walk.walk(root);
  return root;
}

}  // namespace smoothsteer::io
