// What the programs' `--check --work` tests share: a unit's count in a report, and the bytes
// of the float64 values a program's field frame carries. Header-only: each test links the
// program's own library, which brings the field frame and the report.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "coupler/field/field_frame.hpp"
#include "coupler/participant/work_report.hpp"

namespace cosim::testing {

inline std::uint64_t unit(const participant::WorkUnits& units, const std::string& name) {
  for (const auto& [key, count] : units)
    if (key == name) return count;
  ADD_FAILURE() << "no unit " << name;
  return 0;
}

inline std::uint64_t frame_bytes(const field::FieldFrame& frame) {
  std::uint64_t values = 0;
  for (const field::CellField& f : frame.fields) values += f.values.size();
  for (const field::PointSet& p : frame.point_sets) {
    values += p.points.size();
    for (const field::PointAttribute& a : p.attributes) values += a.values.size();
  }
  return values * sizeof(double);
}

}  // namespace cosim::testing
