#include "comparison_report.hpp"

#include "text_table.hpp"

#include <algorithm>

namespace bench {
namespace {

// A verdict shown with a '*': a change in a metric that does not make a regression.
bool informational(const Comparison& c, const MetricVerdict& v) { return v.verdict != Verdict::unchanged && !c.gates(v); }

std::string side(const RunInfo& r) {
  // The default label is the commit's start: not worth saying twice.
  std::string text = r.label.empty() || r.commit.starts_with(r.label) ? r.commit : r.label + " (" + r.commit + ")";
  text += format(", %s v%u on %s, %u repetitions", r.suite.c_str(), r.suite_version, r.hostname.c_str(),
                 r.repetitions);
  return text;
}

std::string about(const Comparison& c) {
  const Thresholds& t = c.options.thresholds;
  std::string text = "baseline:  " + side(c.baseline) + "\ncandidate: " + side(c.candidate) + "\n";
  text += format("%s; a change counts when p < %g, the ratio is off 1 by at least %g%% and the medians by %g ms\n",
                 c.paired ? "interleaved renders compared pair by pair, Wilcoxon signed-rank on the ratios"
                          : "separate runs, Mann-Whitney U",
                 t.alpha, 100.0 * t.min_effect, t.min_ms);
  return text;
}

// `everything`: every metric and image; otherwise the totals and what changed.
TextTable table(const Comparison& c, bool everything) {
  TextTable t{{"case", "metric", "baseline ms", "candidate ms", "ratio", c.paired ? "ratio interval" : "", "p", "verdict"},
              {false, false, true, true, true, true, true, false},
              {}};
  for (const CaseComparison& cc : c.cases) {
    bool first = true;
    const auto row = [&](std::vector<std::string> cells) {
      cells.insert(cells.begin(), first ? cc.name : "");
      t.rows.push_back(std::move(cells));
      first = false;
    };
    if (cc.outcome != CaseOutcome::compared) {
      row({to_string(cc.outcome), "", "", "", "", "", cc.detail});
      continue;
    }
    for (const MetricVerdict& v : cc.metrics) {
      if (!everything && !is_total(v.metric) && v.verdict == Verdict::unchanged) continue;
      const std::string interval =
          v.ratio_interval ? format("%.3f–%.3f", v.ratio_interval->first, v.ratio_interval->second) : "";
      row({v.metric, format("%.3f", v.baseline_ms), format("%.3f", v.candidate_ms), format("%.3f", v.ratio), interval,
           format("%.2g", v.p), to_string(v.verdict) + (informational(c, v) ? "*" : "")});
    }
    // What ran changed: always shown, since such metrics have no verdict to show them by.
    const auto names = [](const std::vector<std::string>& metrics) {
      std::string text;
      for (const std::string& m : metrics) text += (text.empty() ? "" : ", ") + m;
      return text;
    };
    if (!cc.only_in_baseline.empty()) row({"baseline only", "", "", "", "", "", names(cc.only_in_baseline)});
    if (!cc.only_in_candidate.empty()) row({"candidate only", "", "", "", "", "", names(cc.only_in_candidate)});
    const bool image_matters = cc.image.verdict == ImageVerdict::changed || cc.image.verdict == ImageVerdict::not_compared;
    if (everything || image_matters) row({"image", "", "", "", "", "", to_string(cc.image.verdict) + ": " + cc.image.detail});
  }
  if (!c.paired) {  // no interval column
    t.header.erase(t.header.begin() + 5);
    t.numeric.erase(t.numeric.begin() + 5);
    for (auto& r : t.rows)
      if (r.size() > 5) r.erase(r.begin() + 5);
  }
  return t;
}

std::string conclusion(const Comparison& c) {
  std::string text;
  const bool starred = std::ranges::any_of(c.cases, [&](const CaseComparison& cc) {
    return std::ranges::any_of(cc.metrics, [&](const MetricVerdict& v) { return informational(c, v); });
  });
  if (starred) text += "* a pass: where a change comes from, not a regression by itself (--gate-passes)\n";
  text += format("%zu slower (%zu gating), %zu faster, %zu unchanged; %zu images changed; %zu cases failing in the "
                 "candidate: %s\n",
                 c.count(Verdict::slower), c.regressions(), c.count(Verdict::faster), c.count(Verdict::unchanged),
                 c.images_changed(), c.candidate_failures(), c.regression() ? "REGRESSION" : "no regression");
  for (const std::string& w : c.warnings) text += "warning: " + w + "\n";
  return text;
}

}  // namespace

std::string comparison_text(const Comparison& c) { return about(c) + "\n" + table(c, false).text() + "\n" + conclusion(c); }

std::string comparison_markdown(const Comparison& c) {
  std::string md = std::string("## Performance: ") + (c.regression() ? "regression" : "no regression") + "\n\n";
  md += markdown_lines(about(c) + conclusion(c)) + "\n" + table(c, false).markdown();
  md += "\n<details><summary>Every metric and image</summary>\n\n" + table(c, true).markdown() + "\n</details>\n";
  return md;
}

}  // namespace bench
