#include "built_paths.hpp"

namespace smoothsteer::runner::detail {
namespace {

//! Appends an unambiguous text of `node`: type, tag and, with their lengths, scalars and keys.
void append_identity(const YAML::Node& node, std::string& out) {
  const auto text = [&out](const std::string& part) {
    out += std::to_string(part.size());
    out += ':';
    out += part;
  };
  switch (node.Type()) {
    case YAML::NodeType::Scalar:
      out += 'S';
      text(node.Tag());
      text(node.Scalar());
      return;
    case YAML::NodeType::Sequence:
      out += 'L';
      text(node.Tag());
      out += std::to_string(node.size());
      for (const YAML::Node& item : node) append_identity(item, out);
      return;
    case YAML::NodeType::Map:
      out += 'M';
      text(node.Tag());
      out += std::to_string(node.size());
      for (const auto& entry : node) {
        append_identity(entry.first, out);
        append_identity(entry.second, out);
      }
      return;
    case YAML::NodeType::Null:
      out += 'N';
      text(node.Tag());
      return;
    case YAML::NodeType::Undefined:
      out += 'U';
      return;
  }
}

}  // namespace

std::optional<std::string> BuiltPaths::key(const YAML::Node& section,
                                           const std::string& directory) {
  if (section && section.IsMap() && section["type"] && section["type"].IsScalar() &&
      section["type"].Scalar() == "waypoints_csv") {
    return std::nullopt;
  }
  std::string identity = directory;
  identity += '\0';
  append_identity(section, identity);
  return identity;
}

std::optional<BuiltPath> BuiltPaths::find(const std::string& key) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& [kept_key, built] : paths_) {
    if (kept_key == key) return BuiltPath{built.path, built.plan, YAML::Clone(built.resolved)};
  }
  return std::nullopt;
}

void BuiltPaths::keep(const std::string& key, const BuiltPath& built) {
  const std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& [kept_key, kept] : paths_) {
    if (kept_key == key) return;
  }
  if (paths_.size() >= max_paths) paths_.pop_front();
  paths_.emplace_back(key, BuiltPath{built.path, built.plan, YAML::Clone(built.resolved)});
}

BuiltPaths& process_paths() {
  static BuiltPaths paths;
  return paths;
}

}  // namespace smoothsteer::runner::detail
