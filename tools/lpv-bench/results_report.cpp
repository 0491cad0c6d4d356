#include "results_report.hpp"

#include "lab/bench/machine_noise.hpp"
#include "text_table.hpp"

#include <algorithm>

namespace bench {
namespace {

std::string about(const api::BenchResults& r) {
  const auto count = [&](api::BenchCaseStatus s) {
    return std::ranges::count(r.cases, s, &api::BenchCaseResult::status);
  };
  std::string text = format("suite %s v%u", r.suite.c_str(), r.suite_version);
  if (!r.label.empty()) text += " (" + r.label + ")";
  text += format(", %s: %zu cases (%ld ok, %ld skipped, %ld failed), %u repetitions after %u warm-up, %.1f s%s\n",
                 r.mode.c_str(), r.cases.size(), long(count(api::BenchCaseStatus::ok)),
                 long(count(api::BenchCaseStatus::skipped)), long(count(api::BenchCaseStatus::failed)), r.repetitions,
                 r.warmup, r.duration_s, r.complete ? "" : ", stopped early");
  text += format("machine %s (%s, %u cores, %s); device %s, driver %s\n", r.machine.hostname.c_str(),
                 r.machine.cpu_model.c_str(), r.machine.cores, r.machine.os.c_str(), r.device.name.c_str(),
                 r.device.driver.c_str());
  text += format("build %s %s, %s, commit %s%s%s%s\n", r.build.version.c_str(), r.build.build_type.c_str(),
                 r.build.compiler.c_str(), r.build.commit.c_str(), r.build.dirty ? " (with uncommitted changes)" : "",
                 r.build.sanitizers ? ", sanitizers" : "", r.url.empty() ? "" : (", server " + r.url).c_str());
  if (r.noise) {
    const api::BenchSummary probe = api::summarize(r.noise->probe_ms);
    const std::optional<std::string> noisy = too_noisy(*r.noise);  // at the default threshold
    text += format("machine noise: CPU probe %.1f ms, scatter %.1f%%; load %.2f to %.2f; %s\n", probe.median,
                   100.0 * probe.spread, r.noise->load_start, r.noise->load_end,
                   noisy ? ("too noisy to compare with: " + *noisy).c_str() : "steady enough to compare with");
  }
  return text;
}

TextTable table(const api::BenchResults& r) {
  TextTable t{{"case", "metric", "median ms", "min", "max", "spread", "n"}, {false, false, true, true, true, true, true}, {}};
  for (const api::BenchCaseResult& c : r.cases) {
    if (c.status != api::BenchCaseStatus::ok) {
      t.rows.push_back({c.name, api::to_string(c.status)});  // why: below the table
      continue;
    }
    bool first = true;
    for (const api::BenchMetric& metric : c.metrics) {
      const api::BenchSummary s = api::summarize(metric.samples);
      t.rows.push_back({first ? c.name : "", metric.name, format("%.3f", s.median), format("%.3f", s.min),
                        format("%.3f", s.max), format("±%.1f%%", 100.0 * s.spread), std::to_string(s.n)});
      first = false;
    }
  }
  return t;
}

// Why cases were skipped or failed: too long for a table cell.
std::string reasons(const api::BenchResults& r) {
  std::string text;
  for (const api::BenchCaseResult& c : r.cases)
    if (c.status != api::BenchCaseStatus::ok) text += c.name + ": " + api::to_string(c.status) + ": " + c.reason + "\n";
  return text.empty() ? text : "\n" + text;
}

}  // namespace

std::string results_text(const api::BenchResults& results) {
  return about(results) + "\n" + table(results).text() + reasons(results);
}

std::string results_markdown(const api::BenchResults& results) {
  std::string md = "## Benchmark: " + results.suite + " v" + std::to_string(results.suite_version) + "\n\n";
  md += markdown_lines(about(results)) + "\n";
  md += table(results).markdown();
  md += markdown_lines(reasons(results));
  md += "\nspread: median absolute deviation over the median.\n";
  return md;
}

}  // namespace bench
