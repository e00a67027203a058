// Group, link and flush operations with the run file's error policy.
#pragma once

#include <hdf5.h>

#include <string>
#include <vector>

#include "coupler/output/h5_handle.hpp"

namespace cosim::output {

// `properties`: the group's creation properties.
Handle create_group(hid_t parent, const std::string& name, hid_t properties = H5P_DEFAULT);
// A group whose attributes live in its dense storage (a heap) rather than in its header,
// whose messages hold 64 KiB at most: a list of ten thousand names is 160 KiB of
// references (RunFileTest.TenThousandBodiesAreNamed).
Handle create_group_for_large_attributes(hid_t parent, const std::string& name);
Handle open_group(hid_t parent, const std::string& name);
Handle open_or_create_group(hid_t parent, const std::string& name);
bool has_link(hid_t parent, const std::string& name);
// Whether the object `name` links to is a group (false for a dataset).
bool is_group(hid_t parent, const std::string& name);
// The names in a group, in name order.
std::vector<std::string> link_names(hid_t group);
// Unlinks name; its object's space becomes free space of the file.
void delete_link(hid_t parent, const std::string& name);
// Writes everything HDF5 holds in memory for the file (metadata and raw-data caches).
void flush(hid_t file);

}  // namespace cosim::output
