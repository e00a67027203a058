// Owning wrappers for HDF5 ids and the error policy of the run file: a failing HDF5 call or
// a bad value becomes an ObjectError naming the object, and RunFile adds the file name.
#pragma once

#include <hdf5.h>

#include <stdexcept>
#include <string>

namespace cosim::output {

class ObjectError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws ObjectError "<what>: <innermost HDF5 message>" (the HDF5 error stack is the only
// place that says *why*, e.g. "No such file or directory"). `what` must be computed without
// HDF5 calls: any call clears the stack.
[[noreturn]] void fail(const std::string& what);
inline void check(herr_t status, const std::string& what) {
  if (status < 0) fail(what);
}

// One open HDF5 object, closed with the matching H5?close when the handle dies.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle() = default;
  // Takes ownership of id, or throws with `what` if the call that produced it failed.
  Handle(hid_t id, Closer close, const std::string& what) : id_(id), close_(close) {
    if (id < 0) fail(what);
  }
  Handle(Handle&& o) noexcept : id_(o.id_), close_(o.close_) { o.id_ = H5I_INVALID_HID; }
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = o.id_;
      close_ = o.close_;
      o.id_ = H5I_INVALID_HID;
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() { reset(); }

  hid_t get() const { return id_; }

 private:
  void reset() noexcept {
    if (id_ >= 0) close_(id_);
    id_ = H5I_INVALID_HID;
  }
  hid_t id_ = H5I_INVALID_HID;
  Closer close_ = nullptr;
};

// The object's path in its file ("/bodies/ball/time"), for error messages.
std::string path_of(hid_t object);
// The path `name` would have inside `parent`.
std::string child_path(hid_t parent, const std::string& name);

// Silences HDF5's automatic stack printing while alive: errors are reported by exceptions,
// and the caller's own printing setting comes back afterwards.
class QuietErrors {
 public:
  QuietErrors();
  ~QuietErrors();
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

}  // namespace cosim::output
