// Reads back an XDMF sidecar well enough to check it against its HDF5 file: the tags must
// nest (a reader rejects the file otherwise), and every DataItem names a dataset.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace cosim::testing {

struct XdmfDataItem {
  std::vector<std::size_t> dims;  // the Dimensions attribute
  std::string file;               // before the ':' of the item's text
  std::string dataset;            // after it
};

struct XdmfContents {
  std::vector<double> times;  // of the Time elements, in order
  std::vector<XdmfDataItem> items;
};

// Throws std::runtime_error if the document is not a nested XML element tree.
XdmfContents read_xdmf(const std::string& text);

}  // namespace cosim::testing
