#include "coupler/output/h5_handle.hpp"

#include <vector>

namespace cosim::output {
namespace {

herr_t keep_innermost(unsigned n, const H5E_error2_t* err, void* out) {
  if (n == 0 && err->desc != nullptr) *static_cast<std::string*>(out) = err->desc;
  return 0;
}

}  // namespace

void fail(const std::string& what) {
  std::string detail;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, keep_innermost, &detail);
  throw ObjectError(detail.empty() ? what : what + ": " + detail);
}

std::string path_of(hid_t object) {
  const ssize_t n = H5Iget_name(object, nullptr, 0);
  if (n <= 0) return "?";
  std::vector<char> name(static_cast<std::size_t>(n) + 1);
  H5Iget_name(object, name.data(), name.size());
  return name.data();
}

std::string child_path(hid_t parent, const std::string& name) {
  const std::string p = path_of(parent);
  return p == "/" ? "/" + name : p + "/" + name;
}

QuietErrors::QuietErrors() {
  H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

QuietErrors::~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }

}  // namespace cosim::output
