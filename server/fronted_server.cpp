#include "server/fronted_server.hpp"

#include "server/http_errors.hpp"

#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>

#include <algorithm>
#include <arpa/inet.h>
#include <cerrno>
#include <chrono>
#include <cstring>

namespace server {
namespace {

using Clock = std::chrono::steady_clock;

// One request's connection: the bytes the front read first, then the socket. Reading the body
// and writing the response each have one deadline, from their first byte; a body that misses
// its deadline is answered 408 here, and what httplib writes after that is dropped. Reads end
// where the front's framing says the request ends (a chunked body's end is not counted here),
// so that nothing httplib does reads into the next request.
class FrontStream : public httplib::Stream {
 public:
  FrontStream(const HeadReady& connection, std::chrono::milliseconds transfer_timeout)
      : fd_(connection.fd), buffered_(connection.buffered), transfer_timeout_(transfer_timeout),
        read_deadline_(Clock::now() + transfer_timeout), request_end_(request_end(connection)) {}

  bool is_readable() const override { return position_ < buffered_.size() || wait(POLLIN, read_deadline_); }
  bool is_writable() const override { return wait(POLLOUT, write_deadline()); }

  ssize_t read(char* ptr, size_t size) override {
    if (answered_) return -1;
    if (request_end_) {
      if (position_ >= *request_end_) return 0;  // the request's end: as if the client had closed
      size = std::min<std::uint64_t>(size, *request_end_ - position_);
    }
    if (position_ < buffered_.size()) {
      const std::size_t n = std::min(size, buffered_.size() - position_);
      std::memcpy(ptr, buffered_.data() + position_, n);
      position_ += n;
      return ssize_t(n);
    }
    // Read straight into the caller's buffer: nothing beyond what it asks is taken from the
    // socket, so a pipelined next request stays there for the front.
    while (true) {
      if (!wait(POLLIN, read_deadline_)) {
        answer_timeout();
        return -1;
      }
      const ssize_t n = recv(fd_, ptr, size, 0);
      if (n > 0) position_ += std::size_t(n);
      if (n >= 0 || (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) return n;
    }
  }

  ssize_t write(const char* ptr, size_t size) override {
    if (answered_) return ssize_t(size);  // after the 408: dropped
    if (!write_deadline_) write_deadline_ = Clock::now() + transfer_timeout_;
    while (true) {
      if (!wait(POLLOUT, *write_deadline_)) return -1;
      const ssize_t n = send(fd_, ptr, size, MSG_NOSIGNAL);
      if (n >= 0 || (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) return n;
    }
  }

  void get_remote_ip_and_port(std::string& ip, int& port) const override { address(getpeername, ip, port); }
  void get_local_ip_and_port(std::string& ip, int& port) const override { address(getsockname, ip, port); }
  socket_t socket() const override { return fd_; }

  // The connection can serve another request: it was not answered here, and its request was
  // read to its end, so that what follows on it is the next request's start.
  bool reusable() const { return !answered_ && read_to_end(); }
  bool read_to_end() const { return request_end_ && position_ == *request_end_; }
  // The bytes after this request's (a pipelined next request's start).
  std::string leftover() const { return buffered_.substr(std::min<std::size_t>(position_, buffered_.size())); }

 private:
  // Where the request ends, counted from the head's first byte; none for a chunked body.
  static std::optional<std::uint64_t> request_end(const HeadReady& connection) {
    const BodyFraming& body = connection.framed.body;
    switch (body.kind) {
      case BodyFraming::Kind::none: return connection.head_bytes;
      case BodyFraming::Kind::length: return connection.head_bytes + body.length;
      case BodyFraming::Kind::chunked: return std::nullopt;
    }
    return std::nullopt;
  }

  Clock::time_point write_deadline() const { return write_deadline_.value_or(Clock::now() + transfer_timeout_); }

  // Whether `fd_` has `events` before `deadline`.
  bool wait(short events, Clock::time_point deadline) const {
    while (true) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
      if (left <= 0) return false;
      pollfd p{fd_, events, 0};
      const int n = poll(&p, 1, int(std::min<long long>(left, 1000)));
      if (n > 0) return true;  // ready, or an error that the read or write then reports
      if (n < 0 && errno != EINTR) return false;
    }
  }

  void answer_timeout() {
    const std::string response = raw_error_response(
        {408, "request_timeout",
         "the request's body did not arrive within " + std::to_string(transfer_timeout_.count()) +
             " ms (--transfer-timeout-ms)", ""});
    send(fd_, response.data(), response.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
    answered_ = true;
  }

  template <class Get>
  void address(Get get, std::string& ip, int& port) const {
    sockaddr_storage a{};
    socklen_t length = sizeof a;
    ip.clear();
    port = 0;
    if (get(fd_, reinterpret_cast<sockaddr*>(&a), &length) != 0) return;
    char text[INET6_ADDRSTRLEN] = "";
    if (a.ss_family == AF_INET) {
      const auto& v4 = reinterpret_cast<const sockaddr_in&>(a);
      inet_ntop(AF_INET, &v4.sin_addr, text, sizeof text);
      port = ntohs(v4.sin_port);
    } else if (a.ss_family == AF_INET6) {
      const auto& v6 = reinterpret_cast<const sockaddr_in6&>(a);
      inet_ntop(AF_INET6, &v6.sin6_addr, text, sizeof text);
      port = ntohs(v6.sin6_port);
    }
    ip = text;
  }

  int fd_;
  std::string buffered_;
  std::uint64_t position_ = 0;  // bytes read, from the head's first
  std::chrono::milliseconds transfer_timeout_;
  Clock::time_point read_deadline_;
  std::optional<Clock::time_point> write_deadline_;
  std::optional<std::uint64_t> request_end_;
  bool answered_ = false;
};

// The stream of the request this serving thread is answering, for the post-routing handler,
// which httplib calls with the request and response only.
thread_local const FrontStream* answering = nullptr;

}  // namespace

FrontedServer::FrontedServer(const ConnectionLimits& limits) : limits_(limits) {
  // The Keep-Alive header's timeout: the front closes a connection idle this long.
  set_keep_alive_timeout(std::max<time_t>(1, time_t(limits.keep_alive_timeout.count() / 1000)));
  // The wire type of uncompressed JSON (kUncompressedJson), and the one place that decides
  // whether the connection outlives its answer (issue 43): an answer sent before its
  // request's body was read to the end (a refusal, whatever refused it) says "Connection:
  // close", and serve() closes it, so the unread body is never taken for the next request.
  set_post_routing_handler([](const httplib::Request&, httplib::Response& response) {
    if (response.get_header_value("Content-Type") == kUncompressedJson) {
      response.headers.erase("Content-Type");
      response.set_header("Content-Type", "application/json");
    }
    if (!answering || answering->read_to_end()) return;
    response.headers.erase("Keep-Alive");
    response.headers.erase("Connection");
    response.set_header("Connection", "close");
  });
}

std::optional<std::string> FrontedServer::serve(const HeadReady& connection, bool closing) {
  FrontStream stream(connection, limits_.transfer_timeout);
  struct Answering {
    explicit Answering(const FrontStream& s) { answering = &s; }
    ~Answering() { answering = nullptr; }
  } scope(stream);
  bool connection_closed = false;
  const auto restore_empty_fields = [&connection](httplib::Request& request) {
    for (const std::string& name : connection.framed.empty_fields)
      if (!request.has_header(name)) request.headers.emplace(name, "");
  };
  const bool written = process_request(stream, closing, connection_closed, restore_empty_fields);
  if (!written || connection_closed || closing || !stream.reusable()) return std::nullopt;
  return stream.leftover();
}

}  // namespace server
