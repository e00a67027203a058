#include "fluid/body_methods.hpp"

#include <cstdio>

namespace cosim::fluid {

using bodies::BodyTreatment;
using grid::Grid;
using ibm::calibrated_retraction;
using ibm::IbmOptions;
using ibm::ImmersedBoundary;
using ibm::name;
using ibm::Retraction;
using staircase::FbmOptions;
using staircase::FictitiousBoundary;

std::unique_ptr<BodyTreatment> make_bodies(const Grid& grid, const BodyOptions& options) {
  if (const auto* ibm = std::get_if<IbmOptions>(&options)) return std::make_unique<ImmersedBoundary>(grid, *ibm);
  return std::make_unique<FictitiousBoundary>(grid, std::get<FbmOptions>(options));
}

std::string label(const BodyOptions& options) {
  char text[96];
  if (const auto* ibm = std::get_if<IbmOptions>(&options)) {
    const Retraction r = ibm->retraction.value_or(calibrated_retraction(ibm->kernel));
    std::snprintf(text, sizeof text, "ibm %s r%.4f+%.4f", std::string(name(ibm->kernel)).c_str(), r.constant,
                  r.curvature);
  } else {
    std::snprintf(text, sizeof text, "staircase%s offset %.2f",
                  std::get<FbmOptions>(options).subsamples > 1 ? " sub" : "", std::get<FbmOptions>(options).offset);
  }
  return text;
}

}  // namespace cosim::fluid
