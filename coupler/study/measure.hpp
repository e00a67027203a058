// A quantity of interest: one number read from a run file by a small expression.
//
//   measure := max(series) | min(series) | final(series) | mean(series, t0, t1) | abs(measure)
//   series  := body:NAME:DATASET.COMPONENT | field:PARTICIPANT:FIELD[.COMPONENT][@WHERE] | abs(series)
//   WHERE   := [x, y, z] | [x0, y0, z0]..[x1, y1, z1]
//
// DATASET is one of a body's series in the run file (docs/output.md): position, velocity,
// angular_velocity, force, torque; COMPONENT x, y or z. A field series is a grid field's
// volume-weighted mean over the whole grid, over a box of it, or its value in the cell
// holding a point, at each field frame (output.fields_every), its component named for a
// vector field. max, min and final take the written rows (one per
// window with output.every 1, or per field frame); mean is the time average over [t0, t1] s
// by the trapezoidal rule, the ends interpolated, so that levels with different windows
// average the same interval.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "coupler/output/field_means.hpp"

namespace cosim::study {

struct Expression {
  enum class Op { Series, Max, Min, Final, Mean, Abs };
  Op op = Op::Series;
  // Series: the body, or the participant whose field it is; the dataset or field; the
  // component's column (-1: none named, for a scalar field).
  std::string body;
  std::string participant;
  std::string dataset;
  int column = 0;
  output::Region region;                  // a field's: where its mean is taken
  double t0 = 0, t1 = 0;                  // Mean
  std::shared_ptr<const Expression> arg;  // all but Series
  bool is_series() const;
};

struct Measure {
  std::string name;
  std::string text;  // as written
  Expression expression;
};

// Parses `text`; throws ArgumentError "at '<the rest of the text>': <problem>", for the
// caller to say where the text came from (measures.hpp).
Measure parse_measure(const std::string& name, const std::string& text);

// The bodies and the participants whose fields the measure reads, for checking them
// against the scene before anything runs.
std::vector<std::string> bodies_of(const Expression& e);
std::vector<std::string> participants_of(const Expression& e);
const output::Region* region_of(const Expression& e);  // a field series' region; nullptr for a body's
// The latest time a mean reads (0 if none): it must lie within every level's run.
double latest_time(const Expression& e);

// Its value in the run file; throws std::runtime_error naming the file.
double evaluate(const Expression& e, const std::filesystem::path& run_file);

}  // namespace cosim::study
