// Request smuggling (issue 43): requests that a server refuses before it reads their body,
// or whose body's end two readers could place apart, each carrying a hidden request where a
// careless server would take it for the connection's next one. The hidden request deletes a
// stored scene, so that it shows if it ran. Used on a replica directly (test_http_smuggling)
// and through HAProxy (test_http_scale_out).
#pragma once

#include <string>
#include <vector>

namespace server_test {

struct SmugglingCase {
  std::string name;
  std::string bytes;   // sent in one write
  int status = 0;      // lpv-server's answer; through HAProxy, any refusal may come instead
  // The route read the body to its end before refusing: the connection may stay open.
  bool body_read = false;
};

// "DELETE /v1/scenes/<scene_id>": what each case hides.
std::string hidden_delete(const std::string& scene_id);

// The cases for a server whose requests need no token, against scene `scene_id`.
std::vector<SmugglingCase> smuggling_cases(const std::string& scene_id);

// A small glTF binary scene (one quad), to upload as the hidden requests' target.
std::string small_scene_glb();

}  // namespace server_test
