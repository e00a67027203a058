// `cosim run scene.yaml --target NAME=TOL`: the cheapest resolution at which a quantity's
// discretization error meets a tolerance, found, costed, run and checked.
//
// 1. Three cheap levels: the scene coarsened twice and once by the ratio, and as written
//    (study/levels.hpp scaled(): windows, steps and the fluid's cells together).
// 2. Their order and extrapolate give the error model (error_model.hpp) and the scale that
//    reaches the tolerance. A cheap level that already reaches it is the answer.
// 3. That level's cost is estimated here (coupler/estimate) and said before it runs; it is
//    refused when its memory exceeds what the host has available or its time the budget.
// 4. It runs, and the finest three levels give the extrapolate it is judged against.
//
// The levels, their run files and a report.md go to the output folder (docs/study.md).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace cosim::target {

struct Request {
  std::filesystem::path scene;
  std::string target;                 // NAME=TOL
  std::vector<std::string> measures;  // NAME=EXPR, besides the scene's study.measure
  double ratio = 1.5;                 // between the cheap levels
  std::optional<double> budget;       // seconds the chosen level may take
  std::filesystem::path out;          // default runs/target/<scene stem>
  std::string command;                // the command line, for the report
  std::string build;                  // this build's git hash: the cost models fitted to its runs
};

// 0: the target is met; 1: it is not, or no level could be chosen, or one was refused or
// failed (stdout and the report say which). Throws study::ArgumentError before anything
// runs for bad arguments.
int run_to_target(const Request& request);

// "600", "90s", "10m", "2h" as seconds; throws study::ArgumentError naming `text`.
double parse_budget(const std::string& text);

}  // namespace cosim::target
