#include "raw_connection.hpp"

#include <nlohmann/json.hpp>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <regex>

namespace server_test {

int connect_to(int port, const char* source) {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in from{};
  from.sin_family = AF_INET;
  inet_pton(AF_INET, source, &from.sin_addr);
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_port = htons(std::uint16_t(port));
  inet_pton(AF_INET, "127.0.0.1", &to.sin_addr);
  if (fd < 0 || bind(fd, reinterpret_cast<const sockaddr*>(&from), sizeof from) != 0 ||
      connect(fd, reinterpret_cast<const sockaddr*>(&to), sizeof to) != 0) {
    if (fd >= 0) close(fd);
    return -1;
  }
  return fd;
}

bool send_all(int fd, const std::string& text) {
  return send(fd, text.data(), text.size(), MSG_NOSIGNAL) == ssize_t(text.size());
}

std::string answer(int fd, double seconds, bool* closed) {
  using Clock = std::chrono::steady_clock;
  std::string text;
  if (closed) *closed = false;
  const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
  while (Clock::now() < deadline) {
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, 50) <= 0) continue;
    char chunk[4096];
    const ssize_t n = recv(fd, chunk, sizeof chunk, 0);
    if (n <= 0) {
      if (closed) *closed = true;
      break;
    }
    text.append(chunk, std::size_t(n));
  }
  return text;
}

std::string answers_until_quiet(int fd, double first_within, double quiet, bool* closed) {
  bool ended = false;
  std::string text;
  for (double waited = 0.0; !ended && answers_in(text) == 0 && waited < first_within; waited += 0.1)
    text += answer(fd, 0.1, &ended);
  if (!ended) text += answer(fd, quiet, &ended);
  if (closed) *closed = ended;
  return text;
}

std::pair<int, std::string> status_and_code(const std::string& text) {
  if (text.rfind("HTTP/1.1 ", 0) != 0) return {0, ""};
  const int status = std::stoi(text.substr(9, 3));
  const auto body = text.find("\r\n\r\n");
  if (body == std::string::npos) return {status, ""};
  const auto json = nlohmann::json::parse(text.substr(body + 4), nullptr, false);
  return {status, json.is_object() && json.contains("error") ? json["error"].value("code", "") : ""};
}

std::vector<int> statuses_in(const std::string& text) {
  static const std::regex status_line(R"(^HTTP/1\.[01] ([0-9]{3}) )");
  static const std::regex content_length(R"(\r\ncontent-length: *([0-9]+))", std::regex::icase);
  std::vector<int> statuses;
  for (std::size_t at = 0; at < text.size();) {
    std::smatch status;
    const std::string rest = text.substr(at);
    if (!std::regex_search(rest, status, status_line)) break;
    statuses.push_back(std::stoi(status[1]));
    const std::size_t head_end = rest.find("\r\n\r\n");
    if (head_end == std::string::npos) break;
    const std::string head = rest.substr(0, head_end);
    std::smatch length;
    const std::size_t body = std::regex_search(head, length, content_length) ? std::stoul(length[1]) : 0;
    at += head_end + 4 + body;
  }
  return statuses;
}

}  // namespace server_test
