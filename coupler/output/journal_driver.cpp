#include "coupler/output/journal_driver.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/uio.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace cosim::output {
namespace {

using Bytes = std::vector<unsigned char>;
constexpr char kMagic[8] = {'c', 'o', 's', 'i', 'm', 'j', 'l', '1'};
// As sec2: the largest offset an off_t holds.
constexpr haddr_t kMaxAddr = (haddr_t{1} << (8 * sizeof(off_t) - 1)) - 1;

// The file as this process sees it: the bytes on disk, under the writes held since the last
// commit. Held extents never overlap and all lie below `committed`.
struct State {
  std::string path;
  int fd = -1;
  int journal = -1;  // from the first commit on
  bool writable = false;
  dev_t device = 0;
  ino_t inode = 0;
  haddr_t eoa = 0;
  haddr_t eof = 0;        // the file's size as HDF5 sees it
  haddr_t disk = 0;       // the file's size on disk
  haddr_t committed = 0;  // the size the last commit left: what committed metadata can name
  std::map<haddr_t, Bytes> held;
  // A commit failed after its journal became whole: the file may be half written, and only
  // that journal, finished by the next open, mends it. No later commit may write a journal
  // over it.
  bool broken = false;
};

// HDF5 hands the driver back the H5FD_t it returned from open: the state hangs off it.
struct File {
  H5FD_t pub;
  State* state;
};
State& state_of(const H5FD_t* f) { return *reinterpret_cast<const File*>(f)->state; }

// Pushes `what` (with errno's reason) on HDF5's error stack, where fail() finds it.
herr_t error(hid_t minor, const std::string& what) {
  const std::string text = what + ": " + std::strerror(errno);
  H5Epush2(H5E_DEFAULT, __FILE__, "journal driver", __LINE__, H5E_ERR_CLS, H5E_VFL, minor, "%s", text.c_str());
  return -1;
}

// Writes the pieces one after another from `at` on, and moves `at` past them.
bool write_vector(int fd, std::vector<iovec> pieces, off_t& at) {
  std::size_t first = 0;
  while (first < pieces.size()) {
    const ssize_t done = pwritev(fd, pieces.data() + first, static_cast<int>(pieces.size() - first), at);
    if (done < 0 && errno == EINTR) continue;
    if (done <= 0) return false;
    at += done;
    for (auto left = static_cast<std::size_t>(done); left > 0;) {
      const std::size_t n = std::min(left, pieces[first].iov_len);
      pieces[first].iov_base = static_cast<unsigned char*>(pieces[first].iov_base) + n;
      pieces[first].iov_len -= n;
      left -= n;
      if (pieces[first].iov_len == 0) ++first;
    }
    while (first < pieces.size() && pieces[first].iov_len == 0) ++first;
  }
  return true;
}

bool write_all(int fd, const void* data, std::size_t n, off_t at) {
  return write_vector(fd, {{const_cast<void*>(data), n}}, at);
}

bool read_all(int fd, void* out, std::size_t n, off_t at) {
  auto* p = static_cast<unsigned char*>(out);
  while (n > 0) {
    const ssize_t got = pread(fd, p, n, at);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return false;
    p += got;
    n -= static_cast<std::size_t>(got);
    at += got;
  }
  return true;
}

// Reads [at, at + n) of the disk; past its end, zeros (as sec2).
bool read_disk(const State& s, haddr_t at, std::size_t n, unsigned char* out) {
  std::memset(out, 0, n);
  const haddr_t end = std::min<haddr_t>(at + n, s.disk);
  while (at < end) {
    const ssize_t got = pread(s.fd, out, end - at, static_cast<off_t>(at));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return got == 0;
    out += got;
    at += static_cast<haddr_t>(got);
  }
  return true;
}

// The first held extent that ends after `at`.
std::map<haddr_t, Bytes>::iterator first_after(std::map<haddr_t, Bytes>& held, haddr_t at) {
  auto it = held.upper_bound(at);
  if (it != held.begin()) {
    const auto before = std::prev(it);
    if (before->first + before->second.size() > at) return before;
  }
  return it;
}

// Holds [at, at + n), merged with the held extents it overlaps.
void hold(State& s, haddr_t at, const unsigned char* data, std::size_t n) {
  if (n == 0) return;  // an empty extent would shadow the next one held at its address
  const haddr_t end = at + n;
  const auto first = first_after(s.held, at);
  // Within one held extent (a chunk or an object header written again): in place.
  if (first != s.held.end() && first->first <= at && end <= first->first + first->second.size()) {
    std::copy(data, data + n, first->second.begin() + (at - first->first));
    return;
  }
  auto last = first;
  haddr_t lo = at, hi = end;
  for (; last != s.held.end() && last->first < end; ++last) {
    lo = std::min(lo, last->first);
    hi = std::max<haddr_t>(hi, last->first + last->second.size());
  }
  Bytes merged(hi - lo);
  for (auto it = first; it != last; ++it)
    std::copy(it->second.begin(), it->second.end(), merged.begin() + (it->first - lo));
  std::copy(data, data + n, merged.begin() + (at - lo));
  s.held.erase(first, last);
  s.held[lo] = std::move(merged);
}

std::string journal_name(const State& s) { return journal_of(s.path).string(); }

// The journal's first bytes. Its body (count extents, each its address, length and bytes)
// follows them; a header without the magic marks a journal with nothing to do.
struct Header {
  char magic[8];
  std::uint64_t size;   // the file's size after the commit
  std::uint64_t count;  // extents in the body
  std::uint64_t body;   // the body's length in bytes
};

// Copies the held extents into the file and gives it `size`, also where a commit cut off
// after its truncation left extents beyond it.
bool apply(State& s, haddr_t size) {
  for (const auto& [at, bytes] : s.held)
    if (!write_all(s.fd, bytes.data(), bytes.size(), static_cast<off_t>(at))) return false;
  if (ftruncate(s.fd, static_cast<off_t>(size)) != 0) return false;
  s.held.clear();
  s.disk = s.committed = s.eof = size;
  return true;
}

herr_t commit(State& s) {
  if (!s.writable) return 0;
  if (s.broken) {
    errno = EIO;
    return error(H5E_WRITEERROR, "a commit to " + s.path + " failed before: the next open finishes it");
  }
  if (s.held.empty() && s.eof == s.disk) {
    s.committed = s.disk;
    return 0;
  }
  const std::string journal = journal_name(s);
  // Another open of the file may have finished and removed the journal this one writes
  // (recover()): a journal nobody can find would protect nothing.
  struct stat st {};
  if (s.journal >= 0 && (fstat(s.journal, &st) != 0 || st.st_nlink == 0)) {
    close(s.journal);
    s.journal = -1;
  }
  if (s.journal < 0) s.journal = open(journal.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (s.journal < 0) return error(H5E_CANTOPENFILE, "create " + journal);
  Header header{{}, s.eof, s.held.size(), 0};
  std::memcpy(header.magic, kMagic, sizeof kMagic);
  // The body straight from the held extents, a batch of them per system call.
  std::vector<std::uint64_t> extents;
  extents.reserve(2 * s.held.size());
  std::vector<iovec> pieces;
  off_t at = sizeof header;
  const auto write_pieces = [&] {
    const bool ok = write_vector(s.journal, pieces, at);
    pieces.clear();
    return ok;
  };
  for (const auto& [addr, bytes] : s.held) {
    extents.push_back(addr);
    extents.push_back(bytes.size());
    pieces.push_back({&extents[extents.size() - 2], 2 * sizeof(std::uint64_t)});
    pieces.push_back({const_cast<unsigned char*>(bytes.data()), bytes.size()});
    header.body += 2 * sizeof(std::uint64_t) + bytes.size();
    if (pieces.size() >= 512 && !write_pieces()) return error(H5E_WRITEERROR, "write " + journal);
  }
  // Then the header over the previous one: one write of a few bytes, which a kill cannot
  // split, is the commit point. From there on an open finishes the commit.
  if (!write_pieces() || !write_all(s.journal, &header, sizeof header, 0))
    return error(H5E_WRITEERROR, "write " + journal);
  s.broken = true;  // until the journal is applied and marked done
  if (!apply(s, s.eof)) return error(H5E_WRITEERROR, "write " + s.path);
  const char done[sizeof kMagic] = {};
  if (!write_all(s.journal, done, sizeof done, 0)) return error(H5E_WRITEERROR, "write " + journal);
  s.broken = false;
  return 0;
}

// Takes up a journal a kill left behind: into the file if writable, else into memory.
herr_t recover(State& s) {
  const std::string journal = journal_name(s);
  const int fd = open(journal.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return errno == ENOENT ? 0 : error(H5E_CANTOPENFILE, "open " + journal);
  // Shorter than a header: made by a commit that was killed before its first header.
  Header header{};
  Bytes body;
  const bool pending =
      read_all(fd, &header, sizeof header, 0) && std::equal(kMagic, kMagic + sizeof kMagic, header.magic);
  bool ok = true;
  if (pending) {
    body.resize(header.body);
    ok = read_all(fd, body.data(), body.size(), sizeof header);
  }
  close(fd);
  if (!ok) return error(H5E_READERROR, "read " + journal);
  std::size_t at = 0;
  for (std::uint64_t k = 0; pending && k < header.count; ++k) {
    std::uint64_t extent[2];
    if (body.size() - at < sizeof extent) break;
    std::memcpy(extent, body.data() + at, sizeof extent);
    at += sizeof extent;
    if (body.size() - at < extent[1]) break;
    hold(s, extent[0], body.data() + at, extent[1]);
    at += extent[1];
  }
  if (at != body.size()) {
    errno = EINVAL;
    return error(H5E_CANTOPENFILE, "journal " + journal + " is not one this driver wrote");
  }
  if (pending) s.eof = header.size;
  // A journal with nothing to do may be a live writer's, between its commits: left alone.
  if (!s.writable || !pending) return 0;
  if (!apply(s, header.size)) return error(H5E_WRITEERROR, "write " + s.path);
  return unlink(journal.c_str()) == 0 ? 0 : error(H5E_WRITEERROR, "remove " + journal);
}

H5FD_t* open_file(const char* name, unsigned flags, hid_t, haddr_t maxaddr) {
  if (maxaddr == 0 || maxaddr == HADDR_UNDEF || maxaddr > kMaxAddr) {
    errno = EINVAL;
    error(H5E_BADRANGE, "open " + std::string(name));
    return nullptr;
  }
  auto s = std::make_unique<State>();
  s->path = name;
  s->writable = (flags & H5F_ACC_RDWR) != 0;
  int o_flags = (s->writable ? O_RDWR : O_RDONLY) | O_CLOEXEC;
  if (flags & H5F_ACC_CREAT) o_flags |= O_CREAT;
  if (flags & H5F_ACC_EXCL) o_flags |= O_EXCL;
  if (flags & H5F_ACC_TRUNC) {
    o_flags |= O_TRUNC;
    // A journal of the file this one replaces must not be applied to it.
    std::error_code ignored;  // none there, or the open below fails too
    std::filesystem::remove(journal_of(name), ignored);
  }
  s->fd = open(name, o_flags, 0666);
  if (s->fd < 0) {
    error(H5E_CANTOPENFILE, "open " + s->path);
    return nullptr;
  }
  struct stat st {};
  if (fstat(s->fd, &st) != 0) {
    error(H5E_CANTOPENFILE, "stat " + s->path);
    close(s->fd);
    return nullptr;
  }
  s->device = st.st_dev;
  s->inode = st.st_ino;
  s->disk = s->committed = s->eof = static_cast<haddr_t>(st.st_size);
  if (recover(*s) < 0) {
    close(s->fd);
    return nullptr;
  }
  auto* f = new File{};
  f->state = s.release();
  return &f->pub;
}

herr_t close_file(H5FD_t* f) {
  auto* file = reinterpret_cast<File*>(f);
  State& s = *file->state;
  herr_t committed = commit(s);
  if (s.journal >= 0) {
    close(s.journal);
    if (committed >= 0 && unlink(journal_name(s).c_str()) != 0) committed = error(H5E_CANTCLOSEFILE, "remove journal");
  }
  const bool closed = close(s.fd) == 0;
  delete file->state;
  delete file;
  if (committed < 0) return committed;
  return closed ? 0 : error(H5E_CANTCLOSEFILE, "close");
}

int compare(const H5FD_t* a, const H5FD_t* b) {
  const State& x = state_of(a);
  const State& y = state_of(b);
  if (x.device != y.device) return x.device < y.device ? -1 : 1;
  if (x.inode != y.inode) return x.inode < y.inode ? -1 : 1;
  return 0;
}

herr_t query(const H5FD_t*, unsigned long* flags) {
  // As sec2, less its POSIX-compatible handle and SWMR.
  *flags = H5FD_FEAT_AGGREGATE_METADATA | H5FD_FEAT_ACCUMULATE_METADATA | H5FD_FEAT_DATA_SIEVE |
           H5FD_FEAT_AGGREGATE_SMALLDATA;
  return 0;
}

haddr_t get_eoa(const H5FD_t* f, H5FD_mem_t) { return state_of(f).eoa; }
herr_t set_eoa(H5FD_t* f, H5FD_mem_t, haddr_t addr) {
  state_of(f).eoa = addr;
  return 0;
}
haddr_t get_eof(const H5FD_t* f, H5FD_mem_t) { return state_of(f).eof; }

herr_t get_handle(H5FD_t* f, hid_t, void** handle) {
  *handle = &state_of(f).fd;
  return 0;
}

herr_t read_at(H5FD_t* f, H5FD_mem_t, hid_t, haddr_t addr, size_t size, void* buffer) {
  State& s = state_of(f);
  if (size == 0) return 0;  // parallel HDF5 passes empty reads and writes down
  auto* out = static_cast<unsigned char*>(buffer);
  if (!read_disk(s, addr, size, out)) return error(H5E_READERROR, "read " + s.path);
  const haddr_t end = addr + size;
  for (auto it = first_after(s.held, addr); it != s.held.end() && it->first < end; ++it) {
    const haddr_t lo = std::max(addr, it->first);
    const haddr_t hi = std::min<haddr_t>(end, it->first + it->second.size());
    std::memcpy(out + (lo - addr), it->second.data() + (lo - it->first), hi - lo);
  }
  return 0;
}

herr_t write_at(H5FD_t* f, H5FD_mem_t, hid_t, haddr_t addr, size_t size, const void* buffer) {
  State& s = state_of(f);
  if (size == 0) return 0;
  const auto* data = static_cast<const unsigned char*>(buffer);
  const haddr_t end = addr + size;
  if (addr < s.committed) {
    const std::size_t held = std::min(end, s.committed) - addr;
    hold(s, addr, data, held);
    addr += held;
    data += held;
  }
  if (addr < end) {
    // Past what the last commit left: no committed object refers to these bytes yet.
    if (!write_all(s.fd, data, end - addr, static_cast<off_t>(addr))) return error(H5E_WRITEERROR, "write " + s.path);
    s.disk = std::max(s.disk, end);
  }
  s.eof = std::max(s.eof, end);
  return 0;
}

herr_t flush(H5FD_t* f, hid_t, hbool_t) { return commit(state_of(f)); }

// HDF5 sets the file's size to its allocation here; the next commit makes it so on disk.
herr_t truncate(H5FD_t* f, hid_t, hbool_t) {
  State& s = state_of(f);
  if (s.writable) s.eof = s.eoa;
  return 0;
}

herr_t lock(H5FD_t* f, hbool_t rw) {
  State& s = state_of(f);
  if (flock(s.fd, (rw ? LOCK_EX : LOCK_SH) | LOCK_NB) == 0) return 0;
  // A file system without locks (Lustre mounted without flock): unlocked, as sec2 leaves it.
  return errno == ENOSYS ? 0 : error(H5E_CANTLOCKFILE, "lock " + s.path);
}

herr_t unlock(H5FD_t* f) {
  State& s = state_of(f);
  return flock(s.fd, LOCK_UN) == 0 ? 0 : error(H5E_CANTUNLOCKFILE, "unlock " + s.path);
}

const H5FD_class_t kDriver = {"cosim_journal",
                              kMaxAddr,
                              H5F_CLOSE_WEAK,
                              nullptr,  // terminate
                              nullptr,
                              nullptr,
                              nullptr,  // superblock: none of its own
                              0,
                              nullptr,
                              nullptr,
                              nullptr,  // no access properties
                              0,
                              nullptr,
                              nullptr,  // no transfer properties
                              open_file,
                              close_file,
                              compare,
                              query,
                              nullptr,  // type map: the default
                              nullptr,
                              nullptr,  // alloc and free: HDF5's own
                              get_eoa,
                              set_eoa,
                              get_eof,
                              get_handle,
                              read_at,
                              write_at,
                              flush,
                              truncate,
                              lock,
                              unlock,
                              H5FD_FLMAP_DICHOTOMY};

}  // namespace

Handle journaled_access() {
  static const hid_t driver = H5FDregister(&kDriver);
  if (driver < 0) fail("register the journal driver");
  Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "make file access properties");
  check(H5Pset_driver(fapl.get(), driver, nullptr), "select the journal driver");
  // Objects in HDF5 1.8's format at least, which can keep a group's attributes densely
  // (create_group_for_large_attributes); readers since 1.8 (2008) read it.
  check(H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_V18, H5F_LIBVER_LATEST), "ask for the 1.8 format");
  return fapl;
}

std::filesystem::path journal_of(const std::filesystem::path& file) {
  std::filesystem::path journal = file;
  journal += ".journal";
  return journal;
}

bool commit_pending(const std::filesystem::path& file) {
  const int fd = open(journal_of(file).c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  char magic[sizeof kMagic] = {};
  const bool pending = read_all(fd, magic, sizeof magic, 0) && std::equal(kMagic, kMagic + sizeof kMagic, magic);
  close(fd);
  return pending;
}

}  // namespace cosim::output
