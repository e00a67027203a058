// `cosim calibrate`: runs a ladder of small scenes of each built-in program on this host, so
// that the cost models have measurements of different sizes to fit (each run records itself
// like any finished run, marked as calibration), then prints the fitted models.
#pragma once

#include <filesystem>

namespace cosim::estimate {

// `scale` multiplies every calibration run's length (1: about a minute and a half on two cores).
int calibrate(const std::filesystem::path& cosim_executable, double scale);

}  // namespace cosim::estimate
