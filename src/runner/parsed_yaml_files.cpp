#include "parsed_yaml_files.hpp"

#include <filesystem>

#include "smoothsteer/io/bounded_file.hpp"
#include "smoothsteer/io/config_section.hpp"

namespace smoothsteer::runner::detail {

YAML::Node ParsedYamlFiles::copy(const std::string& file) {
  std::string text;
  try {
    text = io::read_bounded_file(file, io::max_yaml_file_bytes, "YAML file");
  } catch (const io::FileReadError& error) {
    throw io::ConfigError(error.what());  // as io::load_yaml_file()
  }
  // Absolute: the same relative name is another file after a change of directory.
  const std::string path = std::filesystem::absolute(file).lexically_normal().string();
  const std::lock_guard<std::mutex> lock(mutex_);
  for (auto it = files_.begin(); it != files_.end(); ++it) {
    if (it->path != path) continue;
    if (it->text == text) return YAML::Clone(it->tree);
    files_.erase(it);  // changed since
    break;
  }
  Parsed parsed{path, "", io::parse_yaml_text(text, file)};
  ++parses_;
  parsed.text = std::move(text);
  YAML::Node copy = YAML::Clone(parsed.tree);
  keep(std::move(parsed));
  return copy;
}

void ParsedYamlFiles::keep(Parsed parsed) {
  if (parsed.text.size() > max_bytes) return;
  std::size_t bytes = parsed.text.size();
  for (const Parsed& kept : files_) bytes += kept.text.size();
  while (!files_.empty() && (files_.size() >= max_files || bytes > max_bytes)) {
    bytes -= files_.front().text.size();
    files_.pop_front();
  }
  files_.push_back(std::move(parsed));
}

std::size_t ParsedYamlFiles::parses() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return parses_;
}

ParsedYamlFiles& process_yaml_files() {
  static ParsedYamlFiles files;
  return files;
}

}  // namespace smoothsteer::runner::detail
