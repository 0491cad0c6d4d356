#include "server/http_front.hpp"

#include "server/http_errors.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/epoll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <unordered_map>

namespace server {
namespace {

using Clock = std::chrono::steady_clock;

// How often deadlines are checked: the front's timeouts are this much late at most.
constexpr int kTickMs = 100;
// A connection closed after its answer (refused, or its body left unread) is read and dropped
// for this long, so that the client reads the answer rather than a reset (closing a socket
// with unread bytes resets it).
constexpr auto kLinger = std::chrono::milliseconds(1000);
// Refused connections lingering at once; past this they are closed at once. With
// --max-connections (512) they keep the front's descriptors under the usual limit of 1024.
constexpr std::size_t kMaxLingering = 256;
// Bytes read from one connection per wake-up: a client that sends without pause (a flood
// lingering after its 431) cannot keep the front from the others and from its deadlines.
constexpr std::size_t kMaxReadPerWake = 256 * 1024;

std::string peer_address(const sockaddr_storage& address) {
  char text[INET6_ADDRSTRLEN] = "";
  if (address.ss_family == AF_INET)
    inet_ntop(AF_INET, &reinterpret_cast<const sockaddr_in&>(address).sin_addr, text, sizeof text);
  else if (address.ss_family == AF_INET6)
    inet_ntop(AF_INET6, &reinterpret_cast<const sockaddr_in6&>(address).sin6_addr, text, sizeof text);
  return text;
}

std::string milliseconds(std::chrono::milliseconds ms) { return std::to_string(ms.count()) + " ms"; }


// A connection the front reads a head from, or (lingering) drains after refusing it.
struct Waiting {
  std::string client;
  std::string buffer;
  std::size_t scanned = 0;  // bytes of `buffer` searched for the head's end
  std::size_t lines = 0;    // line ends among them
  Clock::time_point deadline;
  bool idle = false;       // kept alive, no byte of its next request yet
  bool lingering = false;  // answered and refused: read and dropped until closed
};

// The epoll loop of HttpFront::run, with the connections it holds.
class FrontLoop {
 public:
  FrontLoop(const ConnectionLimits& limits, const HttpFront::Refused& refused, int listening_fd, int wake_fd)
      : limits_(limits), refused_(refused), listening_fd_(listening_fd) {
    epoll_fd_ = epoll_create1(EPOLL_CLOEXEC);
    if (epoll_fd_ < 0) throw std::runtime_error(std::string("epoll_create1: ") + std::strerror(errno));
    const int flags = fcntl(listening_fd, F_GETFL);
    fcntl(listening_fd, F_SETFL, flags | O_NONBLOCK);
    watch(listening_fd);
    watch(wake_fd);
  }
  ~FrontLoop() {
    for (auto& [fd, w] : waiting_) ::close(fd);
    ::close(epoll_fd_);
  }

  // Events for up to one tick; the ready fds.
  std::vector<int> wait() {
    epoll_event events[64];
    const int n = epoll_wait(epoll_fd_, events, 64, kTickMs);
    std::vector<int> fds;
    for (int i = 0; i < n; ++i) fds.push_back(events[i].data.fd);
    return fds;
  }

  void stop_accepting() {
    stopped_accepting_ = true;
    if (!accept_paused_) epoll_ctl(epoll_fd_, EPOLL_CTL_DEL, listening_fd_, nullptr);
  }

  // Accepts every pending connection, refusing those past the caps.
  void accept_all() {
    while (true) {
      sockaddr_storage address{};
      socklen_t length = sizeof address;
      const int fd = accept4(listening_fd_, reinterpret_cast<sockaddr*>(&address), &length,
                             SOCK_NONBLOCK | SOCK_CLOEXEC);
      if (fd < 0) {
        // Out of descriptors or memory: the pending connections stay in the kernel's queue,
        // and the front stops watching for them until its next tick instead of spinning.
        if (errno == EMFILE || errno == ENFILE || errno == ENOBUFS || errno == ENOMEM) pause_accepting();
        return;  // else EAGAIN: none left (or a connection reset before its accept)
      }
      const int on = 1;
      setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);  // the headers and body go out apart
      const std::string client = peer_address(address);
      if (open_ >= limits_.max_connections) {
        refuse(fd, client, {503, "too_many_connections",
                            "the server holds " + std::to_string(open_) +
                                " connections, its most (--max-connections); retry later", ""});
      } else if (const std::size_t held = clients_connections(client); held >= limits_.max_connections_per_client) {
        refuse(fd, client, {503, "too_many_connections",
                            "this address holds " + std::to_string(held) +
                                " connections, its most (--max-connections-per-client); retry later", ""});
      } else {
        ++open_;
        ++per_client_[client];
        Waiting w;
        w.client = client;
        w.deadline = Clock::now() + limits_.head_timeout;
        waiting_.emplace(fd, std::move(w));
        watch(fd);
      }
    }
  }

  // Reads what `fd` has; a head that completes goes to `ready`.
  void read(int fd, std::deque<HeadReady>& ready) {
    const auto found = waiting_.find(fd);
    if (found == waiting_.end()) return;
    Waiting& w = found->second;
    char chunk[16384];
    for (std::size_t taken = 0; taken < kMaxReadPerWake;) {
      const ssize_t n = recv(fd, chunk, sizeof chunk, 0);
      if (n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) {
        close(fd, "");  // the client left
        return;
      }
      if (n < 0) break;
      taken += std::size_t(n);
      if (w.lingering) continue;
      if (w.idle) {  // the first byte of a kept-alive connection's next request
        w.idle = false;
        w.deadline = Clock::now() + limits_.head_timeout;
      }
      w.buffer.append(chunk, std::size_t(n));
      if (!still_reading(fd, w, ready)) return;
    }
  }

  // Refuses what ran past its deadline, and closes what lingered long enough; watches the
  // listening socket again after a pause.
  void expire() {
    if (accept_paused_ && !stopped_accepting_) {
      accept_paused_ = false;
      watch(listening_fd_);
    }
    const auto now = Clock::now();
    std::vector<int> late;
    for (const auto& [fd, w] : waiting_)
      if (now >= w.deadline) late.push_back(fd);
    for (const int fd : late) {
      const Waiting& w = waiting_.at(fd);
      if (w.lingering || w.idle) {
        close(fd, "");  // refused and answered already, or kept alive and not used again
      } else if (w.buffer.empty()) {
        close(fd, "request_timeout");  // connected and silent: closed unanswered
      } else {
        refuse_waiting(fd, {408, "request_timeout",
                            "the request's head did not arrive within " + milliseconds(limits_.head_timeout) +
                                " (--head-timeout-ms)", ""});
      }
    }
  }

  // A connection back from a serving thread: its next request's bytes, or nothing to close it.
  void returned(int fd, const std::string& client, std::optional<std::string> leftover, bool stopping,
                std::deque<HeadReady>& ready) {
    if (!leftover || stopping) {
      // Its response is out; what the client still sends (a body left unread) is drained.
      shutdown(fd, SHUT_WR);
      forget(client);
      linger(fd, client);
      return;
    }
    Waiting w;
    w.client = client;
    w.idle = leftover->empty();
    w.deadline = Clock::now() + (w.idle ? limits_.keep_alive_timeout : limits_.head_timeout);
    w.buffer = std::move(*leftover);
    const auto [at, inserted] = waiting_.emplace(fd, std::move(w));
    watch(fd);
    if (!at->second.buffer.empty()) still_reading(fd, at->second, ready);
  }

  // Closes every connection waiting for a head (stop()).
  void close_waiting() {
    std::vector<int> fds;
    for (const auto& [fd, w] : waiting_) fds.push_back(fd);
    for (const int fd : fds) close(fd, "");
  }

  std::size_t lingering() const { return lingering_; }

 private:
  void pause_accepting() {
    accept_paused_ = true;
    epoll_ctl(epoll_fd_, EPOLL_CTL_DEL, listening_fd_, nullptr);
  }

  void watch(int fd) {
    epoll_event event{};
    event.events = EPOLLIN;
    event.data.fd = fd;
    epoll_ctl(epoll_fd_, EPOLL_CTL_ADD, fd, &event);
  }

  // Whether `fd` still waits for its head's end: false when it has ended (the connection moved
  // to `ready`) or when it is over a cap (refused: `w` may be gone).
  bool still_reading(int fd, Waiting& w, std::deque<HeadReady>& ready) {
    // The end may straddle what was scanned and what came: look 3 bytes back.
    const std::size_t from = w.scanned >= 3 ? w.scanned - 3 : 0;
    const std::size_t end = w.buffer.find("\r\n\r\n", from);
    const std::size_t limit = end == std::string::npos ? w.buffer.size() : end + 4;
    // A head with bare LF line ends never shows a CRLF CRLF: refused at its first, not at its
    // deadline. A head that has ended is checked whole by frame_request below.
    if (end == std::string::npos && find_bare_line_break(w.buffer, from) != std::string::npos) {
      refuse_waiting(fd, bare_line_break_refusal());
      return false;
    }
    for (std::size_t i = w.scanned; i < limit; ++i) w.lines += w.buffer[i] == '\n';
    w.scanned = limit;
    // The request line and the blank one are not header lines.
    const std::size_t header_lines = w.lines > 2 ? w.lines - (end == std::string::npos ? 1 : 2) : 0;
    if (header_lines > limits_.max_header_lines) {
      refuse_waiting(fd, {431, "headers_too_large",
                          "the request's head has more than " + std::to_string(limits_.max_header_lines) +
                              " header lines (--max-header-lines)", ""});
      return false;
    }
    if (limit > limits_.max_head_bytes) {
      refuse_waiting(fd, {431, "headers_too_large",
                          "the request's head is over " + std::to_string(limits_.max_head_bytes) +
                              " bytes (--max-head-bytes)", ""});
      return false;
    }
    if (end == std::string::npos) return true;
    const auto framing = frame_request(std::string_view(w.buffer).substr(0, limit), limits_.max_body_bytes);
    if (const HttpError* refusal = std::get_if<HttpError>(&framing)) {
      refuse_waiting(fd, *refusal);
      return false;
    }
    epoll_ctl(epoll_fd_, EPOLL_CTL_DEL, fd, nullptr);
    ready.push_back({fd, w.client, std::move(w.buffer), limit, std::get<FramedHead>(framing)});
    waiting_.erase(fd);
    return false;
  }

  // Answers `error` at once, best effort (a small answer fits the socket's buffer), and lingers.
  void answer(int fd, const HttpError& error) {
    const std::string response = raw_error_response(error);
    send(fd, response.data(), response.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
    shutdown(fd, SHUT_WR);
  }

  void refuse(int fd, const std::string& client, const HttpError& error) {
    answer(fd, error);
    refused_(error.status, error.code, client);
    linger(fd, client);
  }

  void refuse_waiting(int fd, const HttpError& error) {
    Waiting& w = waiting_.at(fd);
    answer(fd, error);
    refused_(error.status, error.code, w.client);
    forget(w.client);
    w.buffer.clear();
    w.buffer.shrink_to_fit();
    if (lingering_ >= kMaxLingering) {
      epoll_ctl(epoll_fd_, EPOLL_CTL_DEL, fd, nullptr);
      ::close(fd);
      waiting_.erase(fd);
      return;
    }
    ++lingering_;
    w.lingering = true;
    w.deadline = Clock::now() + kLinger;
  }

  // A connection answered for the last time, and no longer counted among the admitted ones:
  // drained until it closes or its time is up, or closed now past the cap.
  void linger(int fd, const std::string& client) {
    if (lingering_ >= kMaxLingering) {
      ::close(fd);
      return;
    }
    ++lingering_;
    Waiting w;
    w.client = client;
    w.lingering = true;
    w.deadline = Clock::now() + kLinger;
    waiting_.emplace(fd, std::move(w));
    watch(fd);
  }

  // Closes a waiting connection; a `code` reports it as closed unanswered.
  void close(int fd, const std::string& code) {
    const auto found = waiting_.find(fd);
    if (found == waiting_.end()) return;
    if (found->second.lingering) {
      --lingering_;
    } else {
      if (!code.empty()) refused_(0, code, found->second.client);
      forget(found->second.client);
    }
    epoll_ctl(epoll_fd_, EPOLL_CTL_DEL, fd, nullptr);
    ::close(fd);
    waiting_.erase(found);
  }

  std::size_t clients_connections(const std::string& client) const {
    const auto found = per_client_.find(client);
    return found == per_client_.end() ? 0 : found->second;
  }

  // An admitted connection is gone: its client's count and the total drop.
  void forget(const std::string& client) {
    --open_;
    if (--per_client_[client] == 0) per_client_.erase(client);
  }

  const ConnectionLimits& limits_;
  const HttpFront::Refused& refused_;
  int listening_fd_;
  int epoll_fd_ = -1;
  std::unordered_map<int, Waiting> waiting_;
  std::unordered_map<std::string, std::size_t> per_client_;  // admitted and not closed
  std::size_t open_ = 0;                                     // admitted and not closed
  std::size_t lingering_ = 0;
  bool accept_paused_ = false;      // out of descriptors: not watching the listening socket
  bool stopped_accepting_ = false;  // stop(): not watching it for good
};

}  // namespace

HttpFront::HttpFront(ConnectionLimits limits, std::size_t threads, Serve serve, Refused refused)
    : limits_(limits), thread_count_(threads), serve_(std::move(serve)), refused_(std::move(refused)) {
  wake_fd_ = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
  if (wake_fd_ < 0) throw std::runtime_error(std::string("eventfd: ") + std::strerror(errno));
}

HttpFront::~HttpFront() {
  stop();
  ::close(wake_fd_);
}

void HttpFront::wake() const {
  const std::uint64_t one = 1;
  [[maybe_unused]] const ssize_t n = ::write(wake_fd_, &one, sizeof one);
}

void HttpFront::stop() {
  stopping_ = true;
  wake();
}

void HttpFront::hand_back(int fd, std::string client, std::optional<std::string> leftover) {
  {
    std::lock_guard lock(mutex_);
    returned_.push_back({fd, std::move(client), std::move(leftover)});
  }
  wake();
}

void HttpFront::serving_thread() {
  while (true) {
    HeadReady connection;
    {
      std::unique_lock lock(mutex_);
      ready_cv_.wait(lock, [&] { return threads_stop_ || !ready_.empty(); });
      if (ready_.empty()) return;
      connection = std::move(ready_.front());
      ready_.pop_front();
    }
    std::optional<std::string> leftover;
    try {
      leftover = serve_(connection, stopping_);
    } catch (...) {
      leftover.reset();  // httplib answers what a handler throws; anything else closes
    }
    hand_back(connection.fd, std::move(connection.client), std::move(leftover));
  }
}

void HttpFront::run(int listening_fd) {
  FrontLoop loop(limits_, refused_, listening_fd, wake_fd_);
  for (std::size_t i = 0; i < thread_count_; ++i) threads_.emplace_back([this] { serving_thread(); });
  std::size_t serving = 0;  // connections handed to the serving threads and not back yet
  bool stopped = false;
  while (!stopped || serving > 0) {
    std::deque<HeadReady> ready;
    for (const int fd : loop.wait()) {
      if (fd == listening_fd) {
        if (!stopping_) loop.accept_all();
      } else if (fd == wake_fd_) {
        std::uint64_t count = 0;
        [[maybe_unused]] const ssize_t n = ::read(wake_fd_, &count, sizeof count);
      } else {
        loop.read(fd, ready);
      }
    }
    if (stopping_ && !stopped) {
      stopped = true;
      loop.stop_accepting();
      loop.close_waiting();
    }
    std::deque<Returned> returned;
    {
      std::lock_guard lock(mutex_);
      returned.swap(returned_);
    }
    for (Returned& r : returned) {
      --serving;
      loop.returned(r.fd, r.client, std::move(r.leftover), stopping_, ready);
    }
    loop.expire();
    if (!ready.empty()) {
      serving += ready.size();
      std::lock_guard lock(mutex_);
      for (HeadReady& h : ready) ready_.push_back(std::move(h));
      ready_cv_.notify_all();
    }
  }
  {
    std::lock_guard lock(mutex_);
    threads_stop_ = true;
  }
  ready_cv_.notify_all();
  for (std::thread& t : threads_) t.join();
  threads_.clear();
}

}  // namespace server
