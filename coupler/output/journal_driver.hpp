// The run file's HDF5 file driver: POSIX I/O as HDF5's default (sec2), but every flush is
// one commit that a kill at any instant leaves either whole or not begun.
//
// HDF5 1.10 updates a file in place, one metadata block after another, and can shrink the
// file before it rewrites the superblock that says its size: a kill in the middle leaves a
// file HDF5 refuses to open. This driver keeps what the last flush left (the committed
// bytes, up to the committed size) intact until the next flush: a write into them is held
// in memory; a write past them (the file's growth: new windows' rows, field steps, objects)
// goes straight to the file, where nothing committed refers to it. A flush then writes the
// held bytes and the new size into <file>.journal behind its header, then the header with
// its magic (one write of 32 bytes, which a kill cannot split: the commit point), copies
// the bytes into the file, sets its size and clears the magic; the journal is removed when
// the file closes. Opening the file with this driver finishes a journal whose magic a kill
// left set (read-only: in memory, the file untouched); a commit that failed after its
// commit point leaves the rest to that open and commits nothing more. No fsync: this
// guards against the process dying, not the machine losing power.
//
// The file and journal descriptors are close-on-exec: participants forked while the file is
// open must not inherit it, nor with it HDF5's lock (flock, as sec2), which would keep
// --resume out after a crash.
#pragma once

#include <filesystem>

#include "coupler/output/h5_handle.hpp"

namespace cosim::output {

// File access properties that select the driver, in HDF5 1.8's format at least.
Handle journaled_access();
// Where the driver keeps the journal of `file`.
std::filesystem::path journal_of(const std::filesystem::path& file);
// Whether `file`'s journal holds a commit under way or cut off by a kill (its header's magic
// set): what the next open of `file` with this driver finishes.
bool commit_pending(const std::filesystem::path& file);

}  // namespace cosim::output
