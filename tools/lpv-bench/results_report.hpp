// A results file for people: where it ran, and per case each metric's median, range and
// spread. Plain text for the terminal, Markdown for --report (job summaries).
#pragma once

#include "api/bench_results.hpp"

#include <string>

namespace bench {

std::string results_text(const api::BenchResults& results);
std::string results_markdown(const api::BenchResults& results);

}  // namespace bench
