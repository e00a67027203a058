// Keeps each run's rate while the console reporter prints as usual, then prints the
// coupler-against-raw table.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench/coupler_roundtrip/cases.hpp"

namespace cosim::bench {

class Summary : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override;
  void print_table(const std::vector<Case>& cases) const;

  static std::string window_name(const Case& c);
  static std::string raw_name(const Case& c);

 private:
  std::map<std::string, double> rate_;  // windows (items) per second, by registered name
};

}  // namespace cosim::bench
