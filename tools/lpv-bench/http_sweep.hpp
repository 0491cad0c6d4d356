// lpv-bench sweep --url URL [--jobs N]: a sweep through a running lpv-server, cut into N parts
// (api::split_sweep) that are sent at once, each on a connection of its own (behind a load
// balancer, each to a replica), then joined: the rows of one sweep, in its order.
#pragma once

#include "lab/accuracy/sweep.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace bench {

// `request`: a valid sweep request. Every part traces the same reference (the seed is the
// request's), so the result's reference is the first part's; it is complete when every part
// is. `parts_done(done, parts)` is called from one thread at a time as parts come back.
// Throws what the first failing part said (its status and the server's message).
accuracy::SweepResult sweep_through(const std::string& url, const nlohmann::json& request, std::uint32_t jobs,
                                    const std::function<void(std::size_t done, std::size_t parts)>& parts_done);

}  // namespace bench
