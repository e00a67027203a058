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

// An Attribute of one DataItem.
struct XdmfAttribute {
  std::string name;
  std::string type;         // AttributeType: Scalar, Vector, Matrix
  std::string center;       // Center: Node, Cell
  std::string number_type;  // the DataItem's NumberType: Float, Int
  XdmfDataItem item;
};

// A grid of points without cells (a point set): Polyvertex topology, XYZ geometry, and the
// attributes after it.
struct XdmfPolyvertex {
  std::string name;
  std::size_t elements = 0;  // the topology's NumberOfElements
  XdmfDataItem points;       // the geometry's one DataItem
  std::vector<XdmfAttribute> attributes{};
};

struct XdmfContents {
  std::vector<double> times;                 // of the Time elements, in order
  std::vector<XdmfDataItem> items;           // all of them, those of the Polyvertex grids too
  std::vector<XdmfPolyvertex> polyvertices;  // in order
};

// Throws std::runtime_error if the document is not a nested XML element tree, or has a
// Polyvertex grid whose geometry is not one DataItem of its NumberOfElements x 3 (so that
// checking every item's dataset against its Dimensions checks the points' too), or whose
// attributes are not node-centred with a row per point.
XdmfContents read_xdmf(const std::string& text);

}  // namespace cosim::testing
