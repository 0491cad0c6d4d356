// Scale-out (docs/server.md, "Replicas behind a load balancer"): three lpv-server replicas on
// one data dir behind real HAProxy with the project's policy (docker/haproxy.cfg), under a
// steady load of renders of a built-in and an uploaded scene. One replica is killed with
// SIGKILL mid-render and restarted, then every replica is restarted in turn with SIGTERM.
// No client request may fail, no scene may be lost, and every replica must answer the same
// request with the same bytes. Prints the requests and throughput of each phase.
#include "data_dir.hpp"
#include "haproxy_process.hpp"
#include "http_checks.hpp"
#include "raw_connection.hpp"
#include "server_process.hpp"
#include "smuggling_cases.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstdio>
#include <map>
#include <mutex>
#include <set>
#include <thread>

namespace server_test {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;
using std::chrono::seconds;

constexpr int kReplicas = 3;
constexpr int kClients = 4;  // renders in flight at all times
const std::filesystem::path kBoxGlb = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";

enum Phase { kBefore, kKilled, kRejoined, kRolling, kAfter, kPhases };
constexpr std::array<const char*, kPhases> kPhaseNames = {"3 replicas", "1 killed (SIGKILL)", "rejoined",
                                                          "rolling restart (SIGTERM)", "after"};

std::string render_body(const std::string& scene) {
  return nlohmann::json{{"scene", scene}, {"output", {{"width", 48}, {"height", 32}}}}.dump();
}

// What the clients saw, per phase and in all.
class Tally {
 public:
  explicit Tally(std::vector<std::string> bodies) : bodies_(std::move(bodies)), first_image_(bodies_.size()) {}

  const std::string& body(std::size_t kind) const { return bodies_[kind]; }
  std::size_t kinds() const { return bodies_.size(); }

  void record(Phase phase, std::size_t kind, const httplib::Result& r) {
    std::lock_guard lock(mutex_);
    ++requests_[phase];
    if (!r || r->status != 200 || !png_size(r->body)) {
      ++failed_[phase];
      failures_.push_back(std::string(kPhaseNames[phase]) + ": " +
                          (r ? "status " + std::to_string(r->status) + " from " + r->get_header_value("X-Replica") +
                                   ": " + r->body.substr(0, 200)
                             : "no answer: " + httplib::to_string(r.error())));
      return;
    }
    const std::string replica = r->get_header_value("X-Replica");
    served_[kind].insert(replica);
    ++answered_[replica];
    if (first_image_[kind].empty()) first_image_[kind] = r->body;
    if (r->body != first_image_[kind]) differing_.push_back(replica + " for request " + bodies_[kind]);
  }

  int answered_by(const std::string& replica) const {
    std::lock_guard lock(mutex_);
    const auto it = answered_.find(replica);
    return it == answered_.end() ? 0 : it->second;
  }
  int requests(Phase p) const { return requests_[p]; }
  int failed(Phase p) const { return failed_[p]; }
  const std::vector<std::string>& failures() const { return failures_; }
  const std::vector<std::string>& differing() const { return differing_; }
  const std::set<std::string>& served(std::size_t kind) { return served_[kind]; }

 private:
  mutable std::mutex mutex_;
  std::vector<std::string> bodies_;              // the requests, one per kind
  std::vector<std::string> first_image_;         // the first image of each kind
  std::map<std::size_t, std::set<std::string>> served_;  // kind -> replicas that answered it
  std::map<std::string, int> answered_;                  // replica -> renders it answered
  std::array<int, kPhases> requests_{}, failed_{};
  std::vector<std::string> failures_, differing_;
};

// kClients threads that keep renders going through the load balancer, alternating the kinds,
// until destroyed.
class SteadyLoad {
 public:
  SteadyLoad(const HaproxyProcess& balancer, Tally& tally) {
    for (int c = 0; c < kClients; ++c)
      clients_.emplace_back([this, &balancer, &tally, c] {
        auto http = balancer.client();
        for (std::size_t n = c; !stop_; ++n) {
          const std::size_t kind = n % tally.kinds();
          const auto answer = http->Post("/v1/render", tally.body(kind), "application/json");
          tally.record(phase_, kind, answer);  // counted in the phase it ended in
        }
      });
  }
  ~SteadyLoad() {
    stop_ = true;
    for (auto& c : clients_) c.join();
  }
  void enter(Phase p) {
    phase_ = p;
    started_[p] = Clock::now();
  }
  // Seconds from the start of `p` to that of the next (or now, for the last).
  double seconds_in(Phase p) const {
    const auto end = p + 1 < kPhases && phase_ > p ? started_[p + 1] : Clock::now();
    return std::chrono::duration<double>(end - started_[p]).count();
  }

 private:
  std::atomic<bool> stop_{false};
  std::atomic<Phase> phase_{kBefore};
  std::array<Clock::time_point, kPhases> started_{};
  std::vector<std::thread> clients_;
};

// Waits up to 20 s until `replica` has answered a render more than `before`: it is back in
// the load balancer's rotation.
bool wait_until_serving(const Tally& tally, const std::string& replica, int before) {
  const auto give_up = Clock::now() + seconds(20);
  while (tally.answered_by(replica) <= before && Clock::now() < give_up) std::this_thread::sleep_for(milliseconds(20));
  return tally.answered_by(replica) > before;
}

// Up to 10 s for `server` to have a render running, so that a kill lands mid-render.
bool wait_until_rendering(const ServerProcess& server) {
  const auto give_up = Clock::now() + seconds(10);
  while (Clock::now() < give_up) {
    if (metric(server, "lpv_renders_in_flight") >= 1) return true;
    std::this_thread::sleep_for(milliseconds(2));
  }
  return false;
}

TEST(ScaleOut, ReplicasBehindHaproxySurviveAKillAndARollingRestartWithoutAFailedRequest) {
  DataDir data;
  const std::vector<std::string> args = {"--data-dir", data.path()};
  std::vector<std::unique_ptr<ServerProcess>> replicas;
  std::vector<Replica> names;
  for (int i = 0; i < kReplicas; ++i) {
    replicas.push_back(std::make_unique<ServerProcess>(args));
    std::string name = "r";
    name += std::to_string(i);  // not "r" + ...: GCC 12 warns falsely (-Wrestrict) on it
    names.push_back({name, replicas.back()->port()});
  }
  // The same replica again on its port, as an orchestrator restarts it, once it is ready;
  // returns once the load balancer sends it renders again.
  Tally* counted = nullptr;
  const auto restart = [&](int i) {
    const int before = counted->answered_by(names[i].name);
    const auto start = Clock::now();
    std::vector<std::string> again = args;
    again.insert(again.end(), {"--port", std::to_string(names[i].port)});
    replicas[i] = std::make_unique<ServerProcess>(again);
    EXPECT_TRUE(wait_until_serving(*counted, names[i].name, before)) << names[i].name << " restarted but got no renders";
    std::printf("%s back in rotation %.1f s after its restart\n", names[i].name.c_str(),
                std::chrono::duration<double>(Clock::now() - start).count());
  };
  HaproxyProcess balancer(names);
  auto http = balancer.client();
  const auto created = http->Post("/v1/scenes", read_file(kBoxGlb), "model/gltf-binary");
  ASSERT_TRUE(created && created->status == 201) << (created ? created->body : httplib::to_string(created.error()));
  const std::string uploaded = nlohmann::json::parse(created->body)["id"];

  Tally tally({render_body("cornell-box"), render_body(uploaded)});
  counted = &tally;
  {
    SteadyLoad load(balancer, tally);
    load.enter(kBefore);
    std::this_thread::sleep_for(seconds(3));

    EXPECT_TRUE(wait_until_rendering(*replicas[1])) << "r1 never had a render in flight to be killed in";
    load.enter(kKilled);
    EXPECT_EQ(replicas[1]->stop(SIGKILL), -1) << "killed by the signal";
    std::this_thread::sleep_for(seconds(3));
    restart(1);
    load.enter(kRejoined);
    std::this_thread::sleep_for(seconds(3));

    load.enter(kRolling);
    for (int i = 0; i < kReplicas; ++i) {
      EXPECT_EQ(replicas[i]->stop(SIGTERM), 0) << names[i].name << " drains and exits 0 on SIGTERM";
      restart(i);
    }
    load.enter(kAfter);
    std::this_thread::sleep_for(seconds(3));

    std::printf("%-27s %8s %9s %7s %11s\n", "phase", "seconds", "requests", "failed", "renders/s");
    for (int p = 0; p < kPhases; ++p) {
      const Phase phase = static_cast<Phase>(p);
      const double s = load.seconds_in(phase);
      std::printf("%-27s %8.1f %9d %7d %11.1f\n", kPhaseNames[p], s, tally.requests(phase), tally.failed(phase),
                  (tally.requests(phase) - tally.failed(phase)) / s);
      EXPECT_GT(tally.requests(phase) - tally.failed(phase), 0) << kPhaseNames[p] << ": no render answered";
    }
  }

  for (const std::string& f : tally.failures()) ADD_FAILURE() << "failed request: " << f;
  for (const std::string& d : tally.differing()) ADD_FAILURE() << "other bytes from " << d;
  for (std::size_t kind = 0; kind < tally.kinds(); ++kind)
    EXPECT_EQ(tally.served(kind).size(), std::size_t(kReplicas)) << "every replica rendered " << tally.body(kind);
  for (int i = 0; i < kReplicas; ++i)
    EXPECT_EQ(replicas[i]->client()->Get("/v1/scenes/" + uploaded)->status, 200)
        << names[i].name << " lost the uploaded scene";
  EXPECT_TRUE(balancer.running()) << balancer.log();
}

// The DELETEs a replica's request log shows it ran.
std::size_t deletes_run(const ServerProcess& replica) {
  const std::string log = replica.log();
  std::size_t n = 0;
  for (std::size_t at = 0; (at = log.find("\"method\":\"DELETE\"", at)) != std::string::npos; ++at) ++n;
  return n;
}

// The request-smuggling suite (smuggling_cases) through HAProxy: HAProxy may refuse a case
// itself or forward it, and may read a framing its own way, but no request may reach a replica
// that HAProxy did not forward as one: every DELETE a replica runs has its answer on the
// client's connection, and a refused request's body never runs.
TEST(ScaleOut, SmuggledRequestsReachNoReplicaThatHaproxyDidNotForward) {
  DataDir data;
  std::vector<std::unique_ptr<ServerProcess>> replicas;
  std::vector<Replica> names;
  for (int i = 0; i < 2; ++i) {
    replicas.push_back(std::make_unique<ServerProcess>(std::vector<std::string>{"--data-dir", data.path()}));
    names.push_back({i == 0 ? "r0" : "r1", replicas.back()->port()});
  }
  HaproxyProcess balancer(names);
  const auto upload = [&] {
    const auto created = balancer.client()->Post("/v1/scenes", small_scene_glb(), "model/gltf-binary");
    return created && (created->status == 201 || created->status == 200) ? nlohmann::json::parse(created->body)["id"].get<std::string>()
                                                                          : std::string();
  };
  const std::string id = upload();
  ASSERT_FALSE(id.empty());
  for (const SmugglingCase& c : smuggling_cases(id)) {
    SCOPED_TRACE(c.name);
    ASSERT_EQ(upload(), id);  // again, should a forwarded DELETE have removed it
    std::size_t before = 0;
    for (const auto& r : replicas) before += deletes_run(*r);
    const int fd = connect_to(balancer.port());
    ASSERT_GE(fd, 0);
    ASSERT_TRUE(send_all(fd, c.bytes));
    // HAProxy keeps the client's connection: until its first answer, then a second for another.
    const std::string text = answers_until_quiet(fd, 3.0, 1.0);
    close(fd);
    std::this_thread::sleep_for(milliseconds(100));  // the replicas' logs written
    std::size_t after = 0;
    for (const auto& r : replicas) after += deletes_run(*r);
    // HAProxy reads some cases its own way, as RFC 9112 lets it (Transfer-Encoding over
    // Content-Length: an empty chunked body, a render of the defaults), and may wait for a
    // body that never comes (the 413 case's): no answer in time.
    const int answers = answers_in(text);
    EXPECT_EQ(after - before, std::size_t(std::max(answers - 1, 0)))
        << "a replica ran a DELETE whose answer the client never got: " << text.substr(0, 400);
    std::printf("%-45s HAProxy answered %d: %s\n", c.name.c_str(), answers, text.substr(0, text.find('\r')).c_str());
  }
  EXPECT_TRUE(balancer.running()) << balancer.log();
}

}  // namespace
}  // namespace server_test
