// The server's front: it owns accept and every request's head, so that slow or many clients
// cannot take the threads that serve requests (issue 29). One thread waits on all connections
// at once (epoll): it refuses connections past the caps (503), reads each request's head
// within its deadline and size caps (408, 431), decides where the request's body ends
// (server/request_framing: a head whose framing is ambiguous is refused, 400, 413 or 501, and
// its connection closed), and only then hands the connection to one of `threads` serving
// threads, which read the body, run the handler and write the response. A connection kept
// alive comes back to the front for its next head; one closed after a response lingers (its
// unread bytes drained for a moment) so that the client reads the answer, not a reset.
//
// httplib 0.11 serves each connection on one thread of a fixed pool from its accept on, with a
// timeout per read only: a client sending a header line every few seconds holds a thread for
// as long as it likes, and a million header lines are read into memory. No HTTP here: the
// front finds where a head ends and counts its lines; what serves a head is `Serve`.
#pragma once

#include "server/connection_limits.hpp"
#include "server/request_framing.hpp"

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace server {

// A connection whose request head has arrived whole.
struct HeadReady {
  int fd = -1;
  std::string client;    // the peer's address, without its port
  std::string buffered;  // the head, and whatever came after it (the body's start)
  std::size_t head_bytes = 0;  // the head's length in `buffered`, its blank line included
  FramedHead framed;           // where the body ends, and the head's empty fields
};

class HttpFront {
 public:
  // Serves one request of `connection` on a serving thread: the bytes left unread after it
  // (a pipelined next request) when the connection stays open, or nothing to close it.
  // `closing`: the front is stopping, so the response should say "Connection: close".
  using Serve = std::function<std::optional<std::string>(const HeadReady& connection, bool closing)>;
  // A connection refused or cut short by the front (for the log and /metrics): the answer's
  // status (0 when it was closed unanswered), its code and the client.
  using Refused = std::function<void(int status, const std::string& code, const std::string& client)>;

  HttpFront(ConnectionLimits limits, std::size_t threads, Serve serve, Refused refused);
  ~HttpFront();
  HttpFront(const HttpFront&) = delete;
  HttpFront& operator=(const HttpFront&) = delete;

  // Accepts on `listening_fd` (bound and listening) and serves until stop(); then closes the
  // connections waiting for a head, lets the serving threads finish the requests they hold
  // (each answered with "Connection: close") and returns. The caller keeps `listening_fd`.
  void run(int listening_fd);
  // From any thread, also before run(): run() returns once the requests in hand are answered.
  void stop();

 private:
  void serving_thread();
  void hand_back(int fd, std::string client, std::optional<std::string> leftover);
  void wake() const;

  ConnectionLimits limits_;
  std::size_t thread_count_;
  Serve serve_;
  Refused refused_;
  int wake_fd_ = -1;  // an eventfd: stop() and the serving threads' hand-backs
  std::atomic<bool> stopping_{false};

  std::mutex mutex_;  // the two queues below
  std::condition_variable ready_cv_;
  std::deque<HeadReady> ready_;  // heads waiting for a serving thread
  struct Returned {
    int fd;
    std::string client;
    std::optional<std::string> leftover;  // none: close it
  };
  std::deque<Returned> returned_;  // connections the serving threads are done with
  bool threads_stop_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace server
