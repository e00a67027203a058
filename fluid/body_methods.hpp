#pragma once
// The two body treatments, and picking one by its options.
#include <memory>
#include <string>
#include <variant>

#include "fluid/staircase/fictitious_boundary.hpp"
#include "fluid/ibm/immersed_boundary.hpp"

namespace cosim::fluid {

using BodyOptions = std::variant<ibm::IbmOptions, staircase::FbmOptions>;

// grid must outlive the result.
std::unique_ptr<bodies::BodyTreatment> make_bodies(const grid::Grid& grid, const BodyOptions& options);

// A short label for tables: "ibm roma3 s3 r0.30", "staircase offset 0.28".
std::string label(const BodyOptions& options);

}  // namespace cosim::fluid
