// A comparison for people: the terminal shows each case's totals and whatever changed;
// the Markdown report (--report) adds every metric, for job summaries.
#pragma once

#include "lab/bench/results_comparison.hpp"

#include <string>

namespace bench {

// "REGRESSION", "no regression" or "INCONCLUSIVE: noisy machine; <why>; ...": what -q prints.
std::string verdict_line(const Comparison& comparison);
std::string comparison_text(const Comparison& comparison);
std::string comparison_markdown(const Comparison& comparison);

}  // namespace bench
