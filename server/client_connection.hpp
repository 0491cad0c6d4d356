// Whether the client of the request being handled has closed its connection, so a render
// nobody waits for leaves the queue. httplib 0.11 (Debian 12) does not hand handlers the
// socket, so it is found once among this process's open sockets by the client's address
// and port, which httplib does record. While a handler runs its socket stays open, so the
// descriptor found cannot be reused by another connection in the meantime.
#pragma once

#include <httplib.h>

namespace server {

class ClientConnection {
 public:
  explicit ClientConnection(const httplib::Request& request);

  // True once the peer has closed (or reset) the connection. A client that pipelines its
  // next request is still there. Never true when the socket could not be identified.
  bool closed() const;

 private:
  int socket_ = -1;
};

}  // namespace server
