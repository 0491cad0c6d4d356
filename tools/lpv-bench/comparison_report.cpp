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
  text += format("%s; a change counts when the ratio's %g%% interval lies wholly beyond 1 +/- %g%% and the medians "
                 "differ by %g ms\n",
                 c.paired ? "interleaved renders compared pair by pair (Hodges-Lehmann interval of the Wilcoxon "
                            "signed-rank test on the ratios)"
                          : "separate runs (Hodges-Lehmann interval of the Mann-Whitney U test)",
                 100.0 * (1.0 - t.alpha), 100.0 * t.min_effect, t.min_ms);
  return text;
}

// `everything`: every metric and image; otherwise the totals and what changed.
TextTable table(const Comparison& c, bool everything) {
  TextTable t{{"case", "metric", "baseline ms", "candidate ms", "ratio", "ratio interval", "p", "verdict"},
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
  return t;
}

std::string conclusion(const Comparison& c) {
  std::string text;
  const bool starred = std::ranges::any_of(c.cases, [&](const CaseComparison& cc) {
    return std::ranges::any_of(cc.metrics, [&](const MetricVerdict& v) { return informational(c, v); });
  });
  if (starred) text += "* a pass: where a change comes from, not a regression by itself (--gate-passes)\n";
  text += format("%zu slower (%zu gating), %zu faster, %zu unchanged; %zu images changed; %zu cases failing in the "
                 "candidate: ",
                 c.count(Verdict::slower), c.regressions(), c.count(Verdict::faster), c.count(Verdict::unchanged),
                 c.images_changed(), c.candidate_failures()) + verdict_line(c) + "\n";
  for (const std::string& w : c.warnings) text += "warning: " + w + "\n";
  return text;
}

}  // namespace

std::string verdict_line(const Comparison& c) {
  switch (c.outcome()) {
    case Outcome::regression: return "REGRESSION";
    case Outcome::no_regression: return "no regression";
    case Outcome::inconclusive: {
      std::string text = "INCONCLUSIVE: noisy machine";
      for (const std::string& why : c.noisy) text += "; " + why;
      return text + "; no verdict on the times, rerun on a quieter machine";
    }
  }
  return "?";
}

std::string comparison_text(const Comparison& c) { return about(c) + "\n" + table(c, false).text() + "\n" + conclusion(c); }

std::string comparison_markdown(const Comparison& c) {
  const std::string outcome = c.outcome() == Outcome::inconclusive ? "inconclusive (noisy machine)"
                              : c.outcome() == Outcome::regression ? "regression"
                                                                  : "no regression";
  std::string md = "## Performance: " + outcome + "\n\n";
  md += markdown_lines(about(c) + conclusion(c)) + "\n" + table(c, false).markdown();
  md += "\n<details><summary>Every metric and image</summary>\n\n" + table(c, true).markdown() + "\n</details>\n";
  return md;
}

}  // namespace bench
