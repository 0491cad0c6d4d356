// The uploaded scenes. Each is named by the SHA-256 of its bytes (so the same file uploaded
// twice is one scene), is validated by loading it before it is kept, and is listed by the
// report made when it was loaded. With a directory, a scene is two files written durably
// (server/durable_files.hpp), its report <id>.json and then its bytes <id>.glb or <id>.gltf,
// so every scene file on disk has its report; they survive restarts. Without a directory,
// scenes live in memory until the server exits.
//
// Thread-safe: HTTP threads add, list and remove scenes while render workers load them.
// Only strings of 64 lowercase hex digits are ever looked up, and a file name is made only
// from such an id, so nothing a client sends becomes a path.
//
// A directory may be shared by several servers (replicas behind a load balancer, docs/
// server.md "Replicas"): the files are the truth and the index only a cache of them. A
// lookup by id reads the disk when the index does not know the id (another replica stored
// it) and checks the scene file is still there when it does (another replica may have
// deleted it); a listing or the totals re-read the directory. Opening removes only what
// interrupted writes left behind long ago (kStaleAge), never another replica's upload in
// progress.
#pragma once

#include "scene/gltf_loader.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace server {

// ^[0-9a-f]{64}$
bool is_scene_id(std::string_view text);

// An upload the store has no room for (its quota of bytes or of scenes): HTTP 507. What is
// stored stays as it is.
class StoreFull : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class SceneStore {
 public:
  // How much the store keeps at most, counted as uploaded: a hostile client could otherwise
  // fill the disk (or, in memory, the RAM) with 64 MiB uploads.
  struct Quota {
    std::uint64_t bytes = 4ull << 30;
    std::size_t scenes = 1000;
  };
  struct Config {
    std::filesystem::path directory;  // empty: in memory only
    scene::LoadLimits limits;         // for uploads, and for loads when rendering
    Quota quota;
  };
  // What opening the directory found, for the start-up log.
  struct Opened {
    std::size_t scenes = 0;
    std::size_t removed_temporary = 0;  // files of writes a crash interrupted
    std::size_t removed_unfinished = 0;  // reports whose scene file was never renamed into place
    std::vector<std::string> skipped;   // files not understood, each with the reason
  };

  // Leftovers of interrupted writes older than this are removed when a store opens: an
  // upload writes its two files within seconds, so younger ones may be another replica's.
  static constexpr std::chrono::minutes kStaleAge{60};

  // Creates the directory if needed, removes what interrupted writes left behind (older than
  // kStaleAge) and reads the reports of the stored scenes. Throws std::filesystem::filesystem_error when the
  // directory cannot be used.
  explicit SceneStore(Config config);
  SceneStore(const SceneStore&) = delete;
  SceneStore& operator=(const SceneStore&) = delete;

  const Opened& opened() const { return opened_; }
  const std::filesystem::path& directory() const { return directory_; }
  bool in_memory() const { return directory_.empty(); }

  struct Added {
    nlohmann::json report;
    bool created = false;  // false: these bytes were stored already; the report is the first upload's
  };
  // Loads `bytes` with scene::load_gltf (external files refused; throws scene::LoadError) and
  // stores them. `name` is what the listing shows; empty: the id. Throws StoreFull when the
  // new scene would pass the quota (the same bytes again are no new scene: never refused),
  // std::system_error when the files cannot be written.
  Added add(std::string_view bytes, const std::string& name);

  // Every stored scene's report, oldest upload first.
  std::vector<nlohmann::json> reports() const;
  std::optional<nlohmann::json> report(const std::string& id) const;
  bool contains(const std::string& id) const;
  // False when no such scene is stored.
  bool remove(const std::string& id);

  // The stored scene, loaded for rendering and named by its id; nullopt when it is not
  // stored (or was removed meanwhile). Throws scene::LoadError when it no longer loads
  // (the limits were lowered since the upload).
  std::optional<scene::Scene> load(const std::string& id) const;

  struct Totals {
    std::size_t scenes = 0;
    std::uint64_t bytes = 0;  // as uploaded
  };
  Totals totals() const;

 private:
  struct Entry {
    nlohmann::json report;
    std::string file;                           // in directory_; empty in memory
    std::shared_ptr<const std::string> bytes;   // in memory only
  };

  void open_directory();
  // The entry of `id` as the directory has it now: read from disk when the index lacks it,
  // dropped from the index when its scene file is gone. With mutex_ held.
  const Entry* current(const std::string& id) const;
  // The index made equal to the directory (scenes other replicas added or removed). With
  // mutex_ held; in memory, nothing to do.
  void refresh() const;
  std::optional<Entry> read_entry(const std::string& id) const;
  // Throws StoreFull when one more scene of `bytes` would pass the quota.
  void check_room(std::uint64_t bytes) const;
  scene::Scene load_bytes(std::string_view bytes, const std::string& id) const;

  const std::filesystem::path directory_;
  const scene::LoadLimits limits_;
  const Quota quota_;
  Opened opened_;
  std::mutex writing_;  // one change of the files at a time; the index stays readable meanwhile
  mutable std::mutex mutex_;
  mutable std::map<std::string, Entry> entries_;  // by id; a cache of the directory's
};

}  // namespace server
