#pragma once
//! \file path_demand.hpp
//! What a reference path asks of the feedforward: its largest curvature and curvature rate
//! (docs/tuning.md, "Feedforward route"), measured on the path itself.

#include "smoothsteer/path/path.hpp"

namespace smoothsteer {

struct PathDemand {
  double max_curvature = 0.0;       //!< max |kappa| [1/m]
  double max_curvature_rate = 0.0;  //!< max |d kappa / ds| [1/m^2], from samples `spacing` apart
};

//! Samples the path every spacing_m (default 5 cm) from s = 0 to its length. A jump of the
//! curvature (a line meeting an arc) shows up as jump / spacing_m: such a path has no finite
//! curvature rate, and the tuner then caps the feedforward's rate by its budget share.
//! Throws std::invalid_argument for a spacing that is not finite and > 0.
PathDemand path_demand(const Path& path, double spacing_m = 0.05);

}  // namespace smoothsteer
