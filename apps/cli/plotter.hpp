#pragma once
//! `--plot`: runs scripts/plot_trace.py on a written trace, without a shell (a path pasted into a
//! shell command line can run commands).

#include <string>

namespace smoothsteer {
class Path;
class PathPlan;
}  // namespace smoothsteer

namespace smoothsteer::cli {

//! Writes the reference path as "x,y" rows (every 0.25 m, at most 20 000 rows) for the plot
//! script, which draws the path itself rather than the closest points of the trace. With
//! `plan`, its pieces one after the other (a path with gear changes) instead of `path`.
void write_path_csv(const Path& path, const std::string& file, const PathPlan* plan = nullptr);

//! The plot script: $SMOOTHSTEER_PLOT_SCRIPT if set, else the first existing of
//! <executable dir>/../share/smoothsteer/plot_trace.py (installed layout),
//! <install prefix>/share/smoothsteer/plot_trace.py and <source tree>/scripts/plot_trace.py.
//! Throws std::runtime_error naming every place it looked.
std::string find_plot_script();

//! Runs /usr/bin/python3 SCRIPT CSV PNG through posix_spawn with an argument vector (no shell,
//! so no character of the paths is interpreted) and waits for it. Throws std::runtime_error
//! with the script's exit status on failure.
void run_plotter(const std::string& script, const std::string& csv, const std::string& png);

}  // namespace smoothsteer::cli
