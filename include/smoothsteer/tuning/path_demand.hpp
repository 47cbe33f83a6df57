#pragma once
//! \file path_demand.hpp
//! What a reference path asks of the feedforward: its largest curvature and curvature rate
//! (docs/tuning.md, "Feedforward route"), measured on the path itself.

#include <memory>

#include "smoothsteer/path/path.hpp"
#include "smoothsteer/tuning/gain_schedule.hpp"

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

//! Largest |d kappa_n / ds| [1/m^2] of the lead wheel's curvature while the rear axle runs
//! exactly on the path: the chain's inverse (invert_chain) of the path's curvature jet, as the
//! controller's rear-axle target computes it, sampled every curvature_jet_step_m. It leads the
//! path's own curvature by about the chain's reach and changes faster: about 1.5 times on the
//! lane change (docs/feedforward.md, "exact rear-axle target"). 0 for order 0.
double lead_curvature_rate_demand(const Path& path, const double* wheelbases, int order);

//! What `tune --path` does: the path's curvature and curvature rate raise the options' bounds
//! (an unknown, infinite rate becomes the path's), and the path becomes the reference path.
//! Returns the path's demand. A null path changes nothing.
PathDemand apply_path_demand(TuningOptions& options, std::shared_ptr<const Path> path);

}  // namespace smoothsteer
