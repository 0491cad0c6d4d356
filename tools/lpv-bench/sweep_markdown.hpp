// The sweep table as Markdown, for docs/accuracy.md and job summaries: one line per row
// with the settings, the frame's GPU time and the errors that matter most for choosing.
#pragma once

#include "api/accuracy_report.hpp"
#include "api/sweep_table.hpp"

#include <string>

namespace bench {

std::string sweep_markdown(const api::SweepTable& table, const api::ReferenceReport& reference);

}  // namespace bench
