#include "output/h5_groups.hpp"

namespace cosim::output {
Handle create_group(hid_t parent, const std::string& name) {
  const std::string where = "group " + child_path(parent, name);
  return Handle(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                "create " + where);
}

Handle open_group(hid_t parent, const std::string& name) {
  const std::string where = "group " + child_path(parent, name);
  return Handle(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), H5Gclose, "open " + where);
}

bool has_link(hid_t parent, const std::string& name) {
  const std::string where = child_path(parent, name);
  const htri_t exists = H5Lexists(parent, name.c_str(), H5P_DEFAULT);
  if (exists < 0) fail("look up " + where);
  return exists > 0;
}

void remove_link(hid_t parent, const std::string& name) {
  const std::string where = child_path(parent, name);
  check(H5Ldelete(parent, name.c_str(), H5P_DEFAULT), "delete " + where);
}

void move_link(hid_t parent, const std::string& from, const std::string& to) {
  const std::string where = child_path(parent, from) + " to " + child_path(parent, to);
  check(H5Lmove(parent, from.c_str(), parent, to.c_str(), H5P_DEFAULT, H5P_DEFAULT),
        "move " + where);
}

void flush(hid_t file) { check(H5Fflush(file, H5F_SCOPE_GLOBAL), "flush"); }

}  // namespace cosim::output
