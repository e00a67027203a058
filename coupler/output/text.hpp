#pragma once
// Text that output files share: XML attribute values, doubles that read back exactly, and
// the UTC time stamp of a run.

#include <string>

namespace cosim::output {

std::string xml_escaped(const std::string& text);
// The shortest text that reads back as the same double.
std::string exact(double value);
// Now, as 2026-11-21T13:33:19Z.
std::string utc_now_iso8601();

}  // namespace cosim::output
