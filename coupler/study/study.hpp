// `cosim study scene.yaml`: what accuracy costs. Runs the scene at several levels of
// resolution, measures quantities of interest in each run file, and reports each one's
// value per level with the run's cost, its observed order, Richardson extrapolate and grid
// convergence index (docs/study.md).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "coupler/output/program_costs.hpp"
#include "coupler/study/convergence.hpp"
#include "coupler/study/measure.hpp"
#include "coupler/study/refinement.hpp"
#include "coupler/study/runner.hpp"

namespace cosim::study {

struct Request {
  std::filesystem::path scene;
  std::vector<std::string> vary;  // KEY=V1,V2,...
  std::vector<std::string> set;   // KEY=VALUE, the same on every level
  std::optional<double> refine;   // or: the factor, with `levels`
  int levels = 3;
  std::vector<std::string> measures;  // NAME=EXPR, added to (or replacing by name) the scene's study.measure
  std::optional<double> order;        // expected order; the scene's study.order otherwise
  std::filesystem::path out;          // default runs/study/<scene stem>
  int jobs = 1;
  std::string command;  // the command line, for the report
};

struct Level {
  std::vector<std::string> values;  // of each varied key, as text
  std::filesystem::path scene, run_file, log;
  Usage usage;
  // Each program's share of the windows' wall time and its peak memory, then the coupler's
  // share, from the run file (output/program_costs.hpp); empty where the run failed.
  std::vector<output::ProgramCost> programs;
};

struct Quantity {
  Measure measure;
  std::vector<std::optional<double>> values;       // per level; none where it could not be read
  std::vector<std::string> problems;               // per level: why there is no value
  std::vector<std::optional<Estimate>> estimates;  // per level: from it and the two levels before
  std::optional<double> reference;                 // what the errors are against: the extrapolate, or the finest value
  bool against_extrapolate = false;
  std::string finding;  // the verdict on the finest three levels, or why there is none
  std::string plot;     // Markdown: its image of error against wall time, or why there is none
};

struct Results {
  std::filesystem::path scene;
  std::string command;
  std::vector<std::string> keys;  // varied, in order; the first gives the ratios
  std::vector<std::string> set;   // KEY = VALUE, the same on every level
  std::vector<Level> levels;
  Ratios ratios;
  std::optional<double> expected_order;
  int jobs = 1;
  std::vector<Quantity> quantities;
};

// Returns the exit status: 0 when every level ran, 1 when one failed (the report says
// which). Throws ArgumentError for bad arguments, before anything runs.
int study(const Request& request);

}  // namespace cosim::study
