#include "server/scene_store.hpp"

#include "api/counted.hpp"

#include "server/durable_files.hpp"
#include "server/scene_report.hpp"
#include "core/sha256.hpp"
#include "core/utc_time.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <span>

namespace server {
namespace {

constexpr std::string_view kGlbMagic = "glTF";

std::string scene_file_name(const std::string& id, std::string_view bytes) {
  return id + (bytes.starts_with(kGlbMagic) ? ".glb" : ".gltf");
}

// A report as add() writes it: the fields reports() and totals() read have their types.
bool is_report_of(const nlohmann::json& report, const std::string& id) {
  return report.is_object() && report.contains("id") && report["id"] == id && report.contains("uploaded_at") &&
         report["uploaded_at"].is_string() && report.contains("bytes") && report["bytes"].is_number_unsigned();
}

std::optional<std::string> read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) return std::nullopt;
  return bytes;
}

}  // namespace

bool is_scene_id(std::string_view text) {
  return text.size() == 64 &&
         std::all_of(text.begin(), text.end(), [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}

SceneStore::SceneStore(Config config)
    : directory_(std::move(config.directory)), limits_(config.limits), quota_(config.quota) {
  if (!directory_.empty()) open_directory();
}

std::optional<SceneStore::Entry> SceneStore::read_entry(const std::string& id) const {
  std::string scene_file;
  for (const char* extension : {".glb", ".gltf"})
    if (std::filesystem::exists(directory_ / (id + extension))) scene_file = id + extension;
  if (scene_file.empty()) return std::nullopt;  // none, or an upload between its two files
  nlohmann::json report = nlohmann::json::parse(read_file(directory_ / (id + ".json")).value_or(""), nullptr, false);
  if (!is_report_of(report, id)) return std::nullopt;
  return Entry{std::move(report), scene_file, nullptr};
}

void SceneStore::open_directory() {
  std::filesystem::create_directories(directory_);
  opened_.removed_temporary = remove_temporary_files(directory_, kStaleAge);
  std::vector<std::string> unfinished;
  for (const auto& item : std::filesystem::directory_iterator(directory_)) {
    const std::string file = item.path().filename().string();
    const std::string id = item.path().stem().string();
    if (item.path().extension() != ".json" || !is_scene_id(id)) continue;  // scene files, or not ours
    if (std::optional<Entry> entry = read_entry(id)) {
      entries_[id] = std::move(*entry);
    } else if (!is_report_of(nlohmann::json::parse(read_file(item.path()).value_or(""), nullptr, false), id)) {
      opened_.skipped.push_back(file + ": not a scene report");
    } else if (older_than(item.path(), kStaleAge)) {
      unfinished.push_back(file);  // the upload stopped between writing its report and its scene
    }
  }
  for (const std::string& file : unfinished) remove_file_durably(directory_, file);
  opened_.removed_unfinished = unfinished.size();
  opened_.scenes = entries_.size();
}

const SceneStore::Entry* SceneStore::current(const std::string& id) const {
  auto it = entries_.find(id);
  if (in_memory()) return it == entries_.end() ? nullptr : &it->second;
  if (it != entries_.end()) {
    if (std::filesystem::exists(directory_ / it->second.file)) return &it->second;
    entries_.erase(it);  // another replica deleted it
    return nullptr;
  }
  std::optional<Entry> stored = read_entry(id);  // another replica may have stored it
  if (!stored) return nullptr;
  return &entries_.emplace(id, std::move(*stored)).first->second;
}

void SceneStore::refresh() const {
  if (in_memory()) return;
  std::map<std::string, Entry> now;
  std::error_code ec;
  for (const auto& item : std::filesystem::directory_iterator(directory_, ec)) {
    const std::string id = item.path().stem().string();
    if (item.path().extension() != ".json" || !is_scene_id(id)) continue;
    if (const auto known = entries_.find(id); known != entries_.end()) {
      if (std::filesystem::exists(directory_ / known->second.file)) now.emplace(id, std::move(known->second));
    } else if (std::optional<Entry> stored = read_entry(id)) {
      now.emplace(id, std::move(*stored));
    }
  }
  if (!ec) entries_ = std::move(now);
}

scene::Scene SceneStore::load_bytes(std::string_view bytes, const std::string& id) const {
  scene::LoadOptions options;
  options.name = id;
  options.limits = limits_;  // external_files_dir stays empty: a file cannot make the loader open a path
  return scene::load_gltf(std::span(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()), options);
}

SceneStore::Added SceneStore::add(std::string_view bytes, const std::string& name) {
  const std::string id = core::sha256_hex(bytes);
  if (std::optional<nlohmann::json> stored = report(id)) return {std::move(*stored), false};
  check_room(bytes.size());  // before the slow part too: a full store decodes nothing
  // Loading is the validation and the slow part: no lock is held meanwhile.
  const scene::Scene scene = load_bytes(bytes, id);

  const std::lock_guard writing(writing_);
  if (std::optional<nlohmann::json> stored = report(id)) return {std::move(*stored), false};  // raced
  check_room(bytes.size());  // again: other uploads may have filled it meanwhile
  Entry entry;
  entry.report = uploaded_scene_report(scene, {id, name.empty() ? id : name, bytes.size(), core::utc_timestamp()});
  if (in_memory()) {
    entry.bytes = std::make_shared<const std::string>(bytes);
  } else {
    // The report before the scene: a scene file on disk always has its report.
    const std::string report_file = id + ".json";
    write_file_durably(directory_, report_file, entry.report.dump() + "\n");
    entry.file = scene_file_name(id, bytes);
    try {
      write_file_durably(directory_, entry.file, bytes);
    } catch (...) {
      remove_file_durably(directory_, report_file);
      throw;
    }
  }
  nlohmann::json created = entry.report;
  const std::lock_guard lock(mutex_);
  entries_.emplace(id, std::move(entry));
  return {std::move(created), true};
}

std::vector<nlohmann::json> SceneStore::reports() const {
  std::vector<nlohmann::json> all;
  {
    const std::lock_guard lock(mutex_);
    refresh();
    for (const auto& [id, entry] : entries_) all.push_back(entry.report);
  }
  std::stable_sort(all.begin(), all.end(), [](const nlohmann::json& a, const nlohmann::json& b) {
    return a.value("uploaded_at", "") < b.value("uploaded_at", "");
  });
  return all;
}

std::optional<nlohmann::json> SceneStore::report(const std::string& id) const {
  if (!is_scene_id(id)) return std::nullopt;
  const std::lock_guard lock(mutex_);
  const Entry* entry = current(id);
  if (!entry) return std::nullopt;
  return entry->report;
}

bool SceneStore::contains(const std::string& id) const {
  if (!is_scene_id(id)) return false;
  const std::lock_guard lock(mutex_);
  return current(id) != nullptr;
}

bool SceneStore::remove(const std::string& id) {
  if (!is_scene_id(id)) return false;
  const std::lock_guard writing(writing_);
  Entry removed;
  {
    const std::lock_guard lock(mutex_);
    if (!current(id)) return false;
    const auto it = entries_.find(id);
    removed = std::move(it->second);
    entries_.erase(it);
  }
  if (!in_memory()) {
    // The scene before its report, for the same reason as in add().
    remove_file_durably(directory_, removed.file);
    remove_file_durably(directory_, id + ".json");
  }
  return true;
}

std::optional<scene::Scene> SceneStore::load(const std::string& id) const {
  if (!is_scene_id(id)) return std::nullopt;
  std::shared_ptr<const std::string> bytes;
  std::string file;
  {
    const std::lock_guard lock(mutex_);
    const Entry* entry = current(id);
    if (!entry) return std::nullopt;
    bytes = entry->bytes;
    file = entry->file;
  }
  if (!bytes) {
    // Read without the lock; a removal meanwhile makes the file vanish, which reads as unknown.
    std::optional<std::string> read = read_file(directory_ / file);
    if (!read) return std::nullopt;
    bytes = std::make_shared<const std::string>(std::move(*read));
  }
  return load_bytes(*bytes, id);
}

void SceneStore::check_room(std::uint64_t bytes) const {
  const Totals stored = totals();
  if (stored.scenes + 1 > quota_.scenes)
    throw StoreFull("the scene store is full: it holds " + api::counted(stored.scenes, "scene") + ", its most (" +
                    "--max-store-scenes); delete one to make room");
  if (stored.bytes + bytes > quota_.bytes)
    throw StoreFull("the scene store is full: " + std::to_string(stored.bytes) + " bytes stored and " +
                    std::to_string(bytes) + " more would pass its quota of " + std::to_string(quota_.bytes) +
                    " bytes (--max-store-bytes); delete scenes to make room");
}

SceneStore::Totals SceneStore::totals() const {
  const std::lock_guard lock(mutex_);
  refresh();
  Totals totals;
  totals.scenes = entries_.size();
  for (const auto& [id, entry] : entries_) totals.bytes += entry.report.value("bytes", std::uint64_t(0));
  return totals;
}

}  // namespace server
