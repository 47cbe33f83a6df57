#include "smoothsteer/io/vehicle_file.hpp"

#include "smoothsteer/io/config_section.hpp"
#include "smoothsteer/io/scenario.hpp"

namespace smoothsteer::io {

VehicleParameters load_vehicle_file(const std::string& yaml_path) {
  return check_vehicle_mapping(load_yaml_file(yaml_path), yaml_path);
}

}  // namespace smoothsteer::io
