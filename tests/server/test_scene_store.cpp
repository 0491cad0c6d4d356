// The scene store without a server: ids, the files it writes, reopening a directory, and
// what a crash can leave behind.
#include "server/scene_store.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace server {
namespace {

const std::filesystem::path kBoxGlb = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

class TemporaryDirectory {
 public:
  TemporaryDirectory() {
    char pattern[] = "/tmp/lpv-store-test-XXXXXX";
    if (!mkdtemp(pattern)) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~TemporaryDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }
  std::set<std::string> files() const {
    std::set<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(path_)) names.insert(entry.path().filename());
    return names;
  }

 private:
  std::filesystem::path path_;
};

TEST(SceneStore, IdsAreSixtyFourLowercaseHexDigitsAndNothingElse) {
  EXPECT_TRUE(is_scene_id(std::string(64, 'a')));
  EXPECT_TRUE(is_scene_id("0123456789abcdef0123456789abcdef0123456789abcdef0123456789abcdef"));
  EXPECT_FALSE(is_scene_id(std::string(63, 'a')));
  EXPECT_FALSE(is_scene_id(std::string(65, 'a')));
  EXPECT_FALSE(is_scene_id(std::string(64, 'A')));
  EXPECT_FALSE(is_scene_id("../" + std::string(61, 'a')));
  EXPECT_FALSE(is_scene_id("cornell-box"));
  EXPECT_FALSE(is_scene_id(""));
}

TEST(SceneStore, KeepsReportAndBytesAndFindsThemAgainWhenReopened) {
  TemporaryDirectory directory;
  const std::string glb = read_file(kBoxGlb);
  std::string id;
  {
    SceneStore store({directory.path(), {}});
    const SceneStore::Added added = store.add(glb, "box");
    EXPECT_TRUE(added.created);
    id = added.report["id"];
    EXPECT_EQ(added.report["name"], "box");
    EXPECT_FALSE(store.add(glb, "other name").created);
    EXPECT_EQ(directory.files(), (std::set<std::string>{id + ".glb", id + ".json"}));
    EXPECT_EQ(store.totals().scenes, 1u);
    EXPECT_EQ(store.totals().bytes, glb.size());
  }
  SceneStore reopened({directory.path(), {}});
  EXPECT_EQ(reopened.opened().scenes, 1u);
  ASSERT_TRUE(reopened.report(id));
  EXPECT_EQ((*reopened.report(id))["name"], "box");
  const std::optional<scene::Scene> loaded = reopened.load(id);
  ASSERT_TRUE(loaded);
  EXPECT_EQ(loaded->name, id);  // renders name it by its id
  EXPECT_EQ(loaded->triangle_count(), 12u);

  EXPECT_TRUE(reopened.remove(id));
  EXPECT_FALSE(reopened.remove(id));
  EXPECT_FALSE(reopened.contains(id));
  EXPECT_FALSE(reopened.load(id));
  EXPECT_TRUE(directory.files().empty());
}

TEST(SceneStore, RefusesWhatDoesNotLoadAndKeepsNothingOfIt) {
  TemporaryDirectory directory;
  scene::LoadLimits limits;
  limits.max_triangles = 5;
  SceneStore store({directory.path(), limits});
  try {
    store.add(read_file(kBoxGlb), "");
    FAIL() << "12 triangles passed a limit of 5";
  } catch (const scene::LoadError& e) {
    EXPECT_EQ(e.kind(), scene::LoadError::Kind::too_complex);
  }
  EXPECT_THROW(store.add("{\"asset\": 1}", ""), scene::LoadError);
  EXPECT_TRUE(store.reports().empty());
  EXPECT_TRUE(directory.files().empty());
}

// Interrupted writes are removed once they are older than kStaleAge; younger ones may be
// another replica's upload in progress on a shared directory, and stay.
TEST(SceneStore, OpeningRemovesStaleInterruptedWritesAndSkipsWhatItDoesNotUnderstand) {
  TemporaryDirectory directory;
  const auto stale = [&](const std::string& file) {
    std::filesystem::last_write_time(directory.path() / file, std::filesystem::file_time_type::clock::now() -
                                                                  SceneStore::kStaleAge - std::chrono::minutes(1));
  };
  std::ofstream(directory.path() / ".partial-abc123") << "half a scene";
  std::ofstream(directory.path() / ".partial-in-progress") << "another replica's upload";
  stale(".partial-abc123");
  const std::string unfinished(64, 'b'), in_progress(64, 'd');  // reports whose scene file is not in place
  for (const std::string& id : {unfinished, in_progress})
    std::ofstream(directory.path() / (id + ".json"))
        << R"({"id": ")" << id << R"(", "uploaded_at": "2025-01-01T00:00:00.000Z", "bytes": 10})";
  stale(unfinished + ".json");
  const std::string garbled(64, 'c');
  std::ofstream(directory.path() / (garbled + ".json")) << "{not json";
  std::ofstream(directory.path() / (garbled + ".glb")) << "glTF";
  std::ofstream(directory.path() / "notes.txt") << "not the store's";

  SceneStore store({directory.path(), {}});
  EXPECT_EQ(store.opened().removed_temporary, 1u);
  EXPECT_EQ(store.opened().removed_unfinished, 1u);
  ASSERT_EQ(store.opened().skipped.size(), 1u);
  EXPECT_NE(store.opened().skipped[0].find(garbled + ".json"), std::string::npos);
  EXPECT_TRUE(store.reports().empty());
  EXPECT_EQ(directory.files(), (std::set<std::string>{".partial-in-progress", in_progress + ".json", garbled + ".json",
                                                      garbled + ".glb", "notes.txt"}));
}

// Two stores on one directory, as two replicas: what one adds the other finds by id and
// lists, what one removes the other no longer finds, loads or counts.
TEST(SceneStore, StoresSharingADirectoryAgree) {
  TemporaryDirectory directory;
  SceneStore a({directory.path(), {}}), b({directory.path(), {}});
  const std::string glb = read_file(kBoxGlb);
  const SceneStore::Added added = a.add(glb, "shared");
  const std::string id = added.report["id"];
  EXPECT_TRUE(b.contains(id));
  ASSERT_TRUE(b.report(id).has_value());
  EXPECT_EQ((*b.report(id))["name"], "shared");
  EXPECT_TRUE(b.load(id).has_value());
  EXPECT_EQ(b.reports().size(), 1u);
  EXPECT_EQ(b.totals().scenes, 1u);
  EXPECT_FALSE(b.add(glb, "again").created) << "the same bytes, stored by the other";
  EXPECT_TRUE(b.remove(id));
  EXPECT_FALSE(a.contains(id));
  EXPECT_FALSE(a.load(id).has_value());
  EXPECT_TRUE(a.reports().empty());
  EXPECT_EQ(a.totals().scenes, 0u);
  EXPECT_FALSE(a.remove(id));
}

TEST(SceneStore, InMemoryWithoutADirectory) {
  SceneStore store({{}, {}});
  EXPECT_TRUE(store.in_memory());
  const SceneStore::Added added = store.add(read_file(kBoxGlb), "");
  const std::string id = added.report["id"];
  EXPECT_EQ(added.report["name"], id);
  ASSERT_TRUE(store.load(id));
  EXPECT_TRUE(store.remove(id));
  EXPECT_FALSE(store.load(id));
}

}  // namespace
}  // namespace server
