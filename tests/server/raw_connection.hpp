// HTTP as bytes on a socket, for the tests of what no client library would send: heads in
// pieces, floods, pipelined and smuggled requests.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace server_test {

// A connection to 127.0.0.1:`port` from `source` (any 127/8 address is loopback on Linux: a
// second client address), or -1.
int connect_to(int port, const char* source = "127.0.0.1");

bool send_all(int fd, const std::string& text);

// What the server sent on `fd` within `seconds`, until it closed the connection or the time
// was up; `closed` (when given) says which.
std::string answer(int fd, double seconds, bool* closed = nullptr);

// For a connection the server may keep open: what it sent until its first whole answer (at
// most `first_within` seconds) and then for `quiet` seconds more, when a second answer would
// have followed the first at once. `closed` (when given) says whether the server closed it.
std::string answers_until_quiet(int fd, double first_within, double quiet, bool* closed = nullptr);

// The first answer's status (0 when there is none) and its JSON error code ("" when it has none).
std::pair<int, std::string> status_and_code(const std::string& text);

// The statuses of the answers `text` holds, in order: each answer's head, then as many body
// bytes as its Content-Length says (a body need not end with a line break: a PNG does not).
// Bytes after the last whole answer that do not start another are ignored.
std::vector<int> statuses_in(const std::string& text);
inline int answers_in(const std::string& text) { return int(statuses_in(text).size()); }

}  // namespace server_test
