// Test support: an SQLite VFS that fails I/O on command, SQLite's own
// habit (its test_vfs.c / ioerr tests). install_failing_vfs() registers it
// as the process's default VFS, wrapping the default there was, so every
// file any connection opens (the database, its -wal, -shm and -journal, a
// shard being merged) goes through it. Once armed at N, the N-th counted call
// fails with an SQLITE_IOERR_* code (or SQLITE_CANTOPEN for an open), and,
// when the fault is persistent, every counted call after it too, until
// disarmed. Counted calls: a file's read, write, truncate, sync, size, lock
// and shared-memory map; the VFS's open, delete and access. Single-threaded:
// the store opens its connections from the calling thread.
#pragma once

#include <sqlite3.h>

#include <stdexcept>
#include <string>

namespace hydrocoef::test {

/// Which file a counted call went to.
enum class VfsFileKind { MainDatabase, Journal, Wal, Other, Count };

struct VfsFaults {
  bool armed = false;
  bool persistent = false;
  long fail_at = 0;                                           ///< the counted call that fails first (1-based; 0: none)
  long calls = 0;                                             ///< counted calls since armed
  long hits = 0;                                              ///< calls failed since armed
  long hits_by_kind[static_cast<int>(VfsFileKind::Count)]{};  ///< of those, by file
  std::string first_fault;                                    ///< e.g. "xSync of the wal"

  /// Counts a call of `method`; true when it is to fail.
  bool fail_now(VfsFileKind kind, const char* method) {
    if (!armed) return false;
    ++calls;
    if (fail_at <= 0) return false;
    if (calls == fail_at || (persistent && calls > fail_at)) {
      if (hits++ == 0) {
        static const char* const kNames[] = {"database", "journal", "wal", "other file"};
        first_fault = std::string(method) + " of the " + kNames[static_cast<int>(kind)];
      }
      ++hits_by_kind[static_cast<int>(kind)];
      return true;
    }
    return false;
  }
  void arm(long n, bool every_call_after) {
    *this = VfsFaults{};
    armed = true;
    fail_at = n;
    persistent = every_call_after;
  }
  void disarm() { armed = false; }
  long hits_on(VfsFileKind kind) const { return hits_by_kind[static_cast<int>(kind)]; }
};

namespace detail {

struct FailingFile {
  sqlite3_file base;
  VfsFileKind kind;
  sqlite3_file* real() { return reinterpret_cast<sqlite3_file*>(this + 1); }
};

inline VfsFaults& vfs_faults() {
  static VfsFaults faults;
  return faults;
}
inline sqlite3_vfs*& wrapped_vfs() {
  static sqlite3_vfs* vfs = nullptr;
  return vfs;
}

inline FailingFile* as_failing(sqlite3_file* file) { return reinterpret_cast<FailingFile*>(file); }
inline sqlite3_file* real_of(sqlite3_file* file) { return as_failing(file)->real(); }
inline bool fail_now(sqlite3_file* file, const char* method) {
  return vfs_faults().fail_now(as_failing(file)->kind, method);
}

inline int file_close(sqlite3_file* f) {
  const int rc = real_of(f)->pMethods->xClose(real_of(f));
  f->pMethods = nullptr;
  return rc;
}
inline int file_read(sqlite3_file* f, void* out, int amount, sqlite3_int64 offset) {
  if (fail_now(f, "xRead")) return SQLITE_IOERR_READ;
  return real_of(f)->pMethods->xRead(real_of(f), out, amount, offset);
}
inline int file_write(sqlite3_file* f, const void* data, int amount, sqlite3_int64 offset) {
  if (fail_now(f, "xWrite")) return SQLITE_IOERR_WRITE;
  return real_of(f)->pMethods->xWrite(real_of(f), data, amount, offset);
}
inline int file_truncate(sqlite3_file* f, sqlite3_int64 size) {
  if (fail_now(f, "xTruncate")) return SQLITE_IOERR_TRUNCATE;
  return real_of(f)->pMethods->xTruncate(real_of(f), size);
}
inline int file_sync(sqlite3_file* f, int flags) {
  if (fail_now(f, "xSync")) return SQLITE_IOERR_FSYNC;
  return real_of(f)->pMethods->xSync(real_of(f), flags);
}
inline int file_size(sqlite3_file* f, sqlite3_int64* size) {
  if (fail_now(f, "xFileSize")) return SQLITE_IOERR_FSTAT;
  return real_of(f)->pMethods->xFileSize(real_of(f), size);
}
inline int file_lock(sqlite3_file* f, int level) {
  if (fail_now(f, "xLock")) return SQLITE_IOERR_LOCK;
  return real_of(f)->pMethods->xLock(real_of(f), level);
}
inline int file_unlock(sqlite3_file* f, int level) { return real_of(f)->pMethods->xUnlock(real_of(f), level); }
inline int file_check_reserved(sqlite3_file* f, int* out) {
  return real_of(f)->pMethods->xCheckReservedLock(real_of(f), out);
}
inline int file_control(sqlite3_file* f, int op, void* arg) {
  return real_of(f)->pMethods->xFileControl(real_of(f), op, arg);
}
inline int file_sector_size(sqlite3_file* f) { return real_of(f)->pMethods->xSectorSize(real_of(f)); }
inline int file_device(sqlite3_file* f) { return real_of(f)->pMethods->xDeviceCharacteristics(real_of(f)); }
inline int file_shm_map(sqlite3_file* f, int page, int size, int extend, void volatile** out) {
  if (fail_now(f, "xShmMap")) return SQLITE_IOERR_SHMMAP;
  return real_of(f)->pMethods->xShmMap(real_of(f), page, size, extend, out);
}
inline int file_shm_lock(sqlite3_file* f, int offset, int n, int flags) {
  return real_of(f)->pMethods->xShmLock(real_of(f), offset, n, flags);
}
inline void file_shm_barrier(sqlite3_file* f) { real_of(f)->pMethods->xShmBarrier(real_of(f)); }
inline int file_shm_unmap(sqlite3_file* f, int delete_flag) {
  return real_of(f)->pMethods->xShmUnmap(real_of(f), delete_flag);
}
inline int file_fetch(sqlite3_file* f, sqlite3_int64 offset, int amount, void** out) {
  return real_of(f)->pMethods->xFetch(real_of(f), offset, amount, out);
}
inline int file_unfetch(sqlite3_file* f, sqlite3_int64 offset, void* page) {
  return real_of(f)->pMethods->xUnfetch(real_of(f), offset, page);
}

/// The wrapper's methods at each version a real file may have (1 to 3): a
/// wrapper never offers a method its real file lacks.
inline const sqlite3_io_methods* io_methods(int version) {
  static const sqlite3_io_methods methods[3] = {
      {1, file_close, file_read, file_write, file_truncate, file_sync, file_size, file_lock, file_unlock,
       file_check_reserved, file_control, file_sector_size, file_device, nullptr, nullptr, nullptr, nullptr, nullptr,
       nullptr},
      {2, file_close, file_read, file_write, file_truncate, file_sync, file_size, file_lock, file_unlock,
       file_check_reserved, file_control, file_sector_size, file_device, file_shm_map, file_shm_lock, file_shm_barrier,
       file_shm_unmap, nullptr, nullptr},
      {3, file_close, file_read, file_write, file_truncate, file_sync, file_size, file_lock, file_unlock,
       file_check_reserved, file_control, file_sector_size, file_device, file_shm_map, file_shm_lock, file_shm_barrier,
       file_shm_unmap, file_fetch, file_unfetch},
  };
  return &methods[(version < 1 ? 1 : version > 3 ? 3 : version) - 1];
}

inline VfsFileKind kind_of(int flags) {
  if (flags & SQLITE_OPEN_MAIN_DB) return VfsFileKind::MainDatabase;
  if (flags & SQLITE_OPEN_MAIN_JOURNAL) return VfsFileKind::Journal;
  if (flags & SQLITE_OPEN_WAL) return VfsFileKind::Wal;
  return VfsFileKind::Other;
}

/// A file named by path alone (delete, access): by its suffix.
inline VfsFileKind kind_of(const char* name) {
  const std::string text = name ? name : "";
  const auto ends_with = [&](const std::string& tail) {
    return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
  };
  if (ends_with("-journal")) return VfsFileKind::Journal;
  if (ends_with("-wal")) return VfsFileKind::Wal;
  return VfsFileKind::Other;
}

inline int vfs_open(sqlite3_vfs*, sqlite3_filename name, sqlite3_file* file, int flags, int* out_flags) {
  auto* failing = as_failing(file);
  failing->base.pMethods = nullptr;
  failing->kind = kind_of(flags);
  if (vfs_faults().fail_now(failing->kind, "xOpen")) return SQLITE_CANTOPEN;
  sqlite3_vfs* real = wrapped_vfs();
  const int rc = real->xOpen(real, name, failing->real(), flags, out_flags);
  if (failing->real()->pMethods) failing->base.pMethods = io_methods(failing->real()->pMethods->iVersion);
  return rc;
}
inline int vfs_delete(sqlite3_vfs*, const char* name, int sync_dir) {
  if (vfs_faults().fail_now(kind_of(name), "xDelete")) return SQLITE_IOERR_DELETE;
  return wrapped_vfs()->xDelete(wrapped_vfs(), name, sync_dir);
}
inline int vfs_access(sqlite3_vfs*, const char* name, int flags, int* out) {
  if (vfs_faults().fail_now(kind_of(name), "xAccess")) return SQLITE_IOERR_ACCESS;
  return wrapped_vfs()->xAccess(wrapped_vfs(), name, flags, out);
}
inline int vfs_full_pathname(sqlite3_vfs*, const char* name, int size, char* out) {
  return wrapped_vfs()->xFullPathname(wrapped_vfs(), name, size, out);
}
inline void* vfs_dl_open(sqlite3_vfs*, const char* name) { return wrapped_vfs()->xDlOpen(wrapped_vfs(), name); }
inline void vfs_dl_error(sqlite3_vfs*, int size, char* out) { wrapped_vfs()->xDlError(wrapped_vfs(), size, out); }
inline void (*vfs_dl_sym(sqlite3_vfs*, void* handle, const char* symbol))(void) {
  return wrapped_vfs()->xDlSym(wrapped_vfs(), handle, symbol);
}
inline void vfs_dl_close(sqlite3_vfs*, void* handle) { wrapped_vfs()->xDlClose(wrapped_vfs(), handle); }
inline int vfs_randomness(sqlite3_vfs*, int size, char* out) {
  return wrapped_vfs()->xRandomness(wrapped_vfs(), size, out);
}
inline int vfs_sleep(sqlite3_vfs*, int microseconds) { return wrapped_vfs()->xSleep(wrapped_vfs(), microseconds); }
inline int vfs_current_time(sqlite3_vfs*, double* out) { return wrapped_vfs()->xCurrentTime(wrapped_vfs(), out); }
inline int vfs_last_error(sqlite3_vfs*, int size, char* out) {
  return wrapped_vfs()->xGetLastError(wrapped_vfs(), size, out);
}
inline int vfs_current_time_int64(sqlite3_vfs*, sqlite3_int64* out) {
  return wrapped_vfs()->xCurrentTimeInt64(wrapped_vfs(), out);
}

}  // namespace detail

/// Registers the failing VFS as the default (once per process) and returns
/// its fault switch.
inline VfsFaults& install_failing_vfs() {
  static sqlite3_vfs vfs = [] {
    sqlite3_vfs* real = sqlite3_vfs_find(nullptr);
    if (!real || real->iVersion < 2) throw std::runtime_error("no default SQLite VFS of version 2 or later to wrap");
    detail::wrapped_vfs() = real;
    sqlite3_vfs v{};
    v.iVersion = 2;
    v.szOsFile = static_cast<int>(sizeof(detail::FailingFile)) + real->szOsFile;
    v.mxPathname = real->mxPathname;
    v.zName = "hydrocoef-test-failing";
    v.xOpen = detail::vfs_open;
    v.xDelete = detail::vfs_delete;
    v.xAccess = detail::vfs_access;
    v.xFullPathname = detail::vfs_full_pathname;
    v.xDlOpen = detail::vfs_dl_open;
    v.xDlError = detail::vfs_dl_error;
    v.xDlSym = detail::vfs_dl_sym;
    v.xDlClose = detail::vfs_dl_close;
    v.xRandomness = detail::vfs_randomness;
    v.xSleep = detail::vfs_sleep;
    v.xCurrentTime = detail::vfs_current_time;
    v.xGetLastError = detail::vfs_last_error;
    v.xCurrentTimeInt64 = detail::vfs_current_time_int64;
    return v;
  }();
  static const int registered = sqlite3_vfs_register(&vfs, 1);
  if (registered != SQLITE_OK) throw std::runtime_error("sqlite3_vfs_register failed");
  return detail::vfs_faults();
}

}  // namespace hydrocoef::test
