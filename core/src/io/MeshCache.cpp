// The cache of meshes read last: see MeshCache.h.
#include "io/MeshCache.h"

#include "raylab/core/Limits.h"
#include "raylab/core/MeshIO.h"

#include <deque>
#include <memory>
#include <mutex>
#include <optional>

#include <sys/stat.h>

namespace raylab::meshcache {

namespace {

/// A file as it was when read: a change of any of these reads it again.
struct FileState {
  std::string path;
  off_t size = 0;
  long long modifiedNs = 0;
  ino_t inode = 0;
  dev_t device = 0;
  bool operator==(const FileState& o) const {
    return path == o.path && size == o.size && modifiedNs == o.modifiedNs && inode == o.inode &&
           device == o.device;
  }
};

struct Entry {
  FileState file;
  std::shared_ptr<const TriangleMesh> mesh;
};

std::mutex g_mutex;
std::deque<Entry> g_entries;  ///< Most recent first.

constexpr std::size_t kMaxEntries = 4;

std::optional<FileState> stateOf(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
  return FileState{path, st.st_size,
                   (long long)st.st_mtim.tv_sec * 1000000000LL + st.st_mtim.tv_nsec, st.st_ino,
                   st.st_dev};
}

}  // namespace

TriangleMesh load(const std::string& path) {
  const std::optional<FileState> state = stateOf(path);
  if (state) {
    const std::lock_guard<std::mutex> lock(g_mutex);
    for (const Entry& e : g_entries)
      if (e.file == *state) return *e.mesh;
  }
  auto mesh = std::make_shared<const TriangleMesh>(MeshIO::load(path));
  // Kept only when the file did not change while it was read.
  if (state && stateOf(path) == state) {
    const std::lock_guard<std::mutex> lock(g_mutex);
    g_entries.push_front(Entry{*state, mesh});
    std::size_t triangles = 0, kept = 0;
    for (const Entry& e : g_entries) {
      triangles += e.mesh->triangles().size();
      if (kept == kMaxEntries || (kept > 0 && triangles > limits::kMaxMeshTriangles)) break;
      ++kept;
    }
    g_entries.resize(kept);
  }
  return *mesh;
}

}  // namespace raylab::meshcache
