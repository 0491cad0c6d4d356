#include "tools/common/program_main.hpp"

#include "api/request_error.hpp"

#include <cstdio>

namespace tools {

int run_program(const char* name, const std::function<int()>& body) {
  try {
    return body();
  } catch (const UsageError& e) {
    std::fprintf(stderr, "%s: %s\n%s", name, e.what(), e.hint().c_str());
    return kExitBadInput;
  } catch (const api::RequestError& e) {
    std::fprintf(stderr, "%s: bad request: %s\n", name, e.what());
    return kExitBadInput;
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s: %s\n", name, e.what());
    return e.status();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", name, e.what());
    return kExitFailure;
  }
}

}  // namespace tools
