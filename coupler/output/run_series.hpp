// Every time series of a run, one row per committed window:
//   /bodies/<name>/{time, position, orientation, velocity, angular_velocity, force, torque}
//   /coupling/{window, time, iterations, residual, wall_seconds}
//   /coupling/participants/<name>/{wall_seconds, substeps, field_bytes}
#pragma once

#include <hdf5.h>

#include <string>
#include <vector>

#include "coupler/output/run_file.hpp"
#include "coupler/output/series.hpp"

namespace cosim::output {

class RunSeries {
 public:
  static RunSeries create(hid_t file, const std::vector<std::string>& bodies,
                          const std::vector<std::string>& participants);
  static RunSeries open(hid_t file, const std::vector<std::string>& bodies,
                        const std::vector<std::string>& participants);

  // Checks the whole record before writing, so a malformed one leaves no partial row.
  void append(const WindowRecord& w);
  // Keeps the windows whose end time is <= time (the coupling time column decides for
  // every series, so they all stay the same length).
  void cut_after(double time);
  hsize_t windows() const;

 private:
  enum class Mode { Create, Open };
  struct Body {
    Series time;
    std::vector<Series> slices;  // kBodySlices order
  };
  RunSeries() = default;
  static RunSeries make(hid_t file, const std::vector<std::string>& bodies,
                        const std::vector<std::string>& participants, Mode mode);
  std::vector<Series*> all();

  std::vector<std::string> participant_names_;
  std::vector<Series> coupling_;                   // kCoupling order
  std::vector<Body> bodies_;                       // scene body order
  std::vector<std::vector<Series>> participants_;  // kParticipant order each
};

}  // namespace cosim::output
