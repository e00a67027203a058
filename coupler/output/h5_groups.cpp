#include "coupler/output/h5_groups.hpp"

namespace cosim::output {
Handle create_group(hid_t parent, const std::string& name, hid_t properties) {
  const std::string where = "group " + child_path(parent, name);
  return Handle(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, properties, H5P_DEFAULT), H5Gclose, "create " + where);
}

Handle create_group_for_large_attributes(hid_t parent, const std::string& name) {
  const std::string where = "group " + child_path(parent, name);
  const Handle properties(H5Pcreate(H5P_GROUP_CREATE), H5Pclose, "make the properties of " + where);
  check(H5Pset_attr_phase_change(properties.get(), 0, 0), "store the attributes of " + where + " densely");
  return create_group(parent, name, properties.get());
}

Handle open_group(hid_t parent, const std::string& name) {
  const std::string where = "group " + child_path(parent, name);
  return Handle(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), H5Gclose, "open " + where);
}

Handle open_or_create_group(hid_t parent, const std::string& name) {
  return has_link(parent, name) ? open_group(parent, name) : create_group(parent, name);
}

bool has_link(hid_t parent, const std::string& name) {
  const std::string where = child_path(parent, name);
  const htri_t exists = H5Lexists(parent, name.c_str(), H5P_DEFAULT);
  if (exists < 0) fail("look up " + where);
  return exists > 0;
}

bool is_group(hid_t parent, const std::string& name) {
  Handle object(H5Oopen(parent, name.c_str(), H5P_DEFAULT), H5Oclose, "open " + child_path(parent, name));
  return H5Iget_type(object.get()) == H5I_GROUP;
}

std::vector<std::string> link_names(hid_t group) {
  std::vector<std::string> names;
  const auto collect = [](hid_t, const char* name, const H5L_info_t*, void* out) -> herr_t {
    static_cast<std::vector<std::string>*>(out)->emplace_back(name);
    return 0;
  };
  check(H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &names), "list " + path_of(group));
  return names;
}

void delete_link(hid_t parent, const std::string& name) {
  const std::string where = child_path(parent, name);
  check(H5Ldelete(parent, name.c_str(), H5P_DEFAULT), "delete " + where);
}

void flush(hid_t file) { check(H5Fflush(file, H5F_SCOPE_GLOBAL), "flush"); }

}  // namespace cosim::output
