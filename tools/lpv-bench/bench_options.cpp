#include "bench_options.hpp"

#include "core/command_line.hpp"

#include <charconv>
#include <functional>
#include <sstream>
#include <string_view>

namespace bench {

std::string usage(const std::vector<std::string>& suites) {
  std::string names;
  for (const std::string& name : suites) names += (names.empty() ? "" : ", ") + name;
  return R"(usage: lpv-bench sweep REQUEST.json|- [options]
       lpv-bench diff REQUEST.json|- [options]
       lpv-bench run SUITE [options]
       lpv-bench compare BASELINE.json CANDIDATE.json [options]
       lpv-bench ab --a LPV_BENCH_A --b LPV_BENCH_B SUITE [options]
       lpv-bench worker SUITE [options]
       lpv-bench budget [SCENE...] [options]

sweep    renders the reference once, then every configuration of LPV settings the
         request lists (the schema of POST /v1/sweep), and writes the accuracy-versus-
         time table: sweep.json, sweep.csv, sweep.md (Markdown) and sweep.svg (error
         against GPU time, Pareto front highlighted). A progress bar on standard error.
         With --url, a server sweeps (in --jobs parts at once) and this writes the files.
diff     compares a render with a second setting or with the reference (the schema of
         POST /v1/compare): writes base.png, other.png, difference.png (heat map),
         base.exr, other.exr (linear) and compare.json (metrics, stats, reference).
run      times a benchmark suite (a file, or the name of one in bench/suites: below):
         per case an image render, warm-up renders, then timed repetitions; writes
         the results (bench/results.schema.json) and prints a summary table.
compare  a candidate's results against a baseline's: per case and metric the ratio,
         its confidence interval (Hodges-Lehmann, Mann-Whitney U) and a verdict: slower
         or faster only when the whole interval is beyond the minimum effect; and
         whether the image changed.
ab       runs the suite with two builds' lpv-bench taking turns render by render (A B,
         B A, ...) and compares them pair by pair (the interval of the Wilcoxon
         signed-rank test on the ratios): the comparison that holds on a shared
         machine. Writes ab.json (the comparison), a.json and b.json (each build's
         results).
worker   one build's side of ab: renders the suite's cases when told to on standard input
         and answers on standard output (the build must have it: ab starts it).
budget   how well requests with budget_ms meet their budgets: per scene (every built-in
         one by default), the default frame's time T, then requests with budgets of T/2,
         T, 2T and 4T, each against a full sweep of the same frame: whether the chosen
         frame took at most 1.1 times its budget, and whether its error is within 10% of
         the most accurate sweep row that fits the budget. Writes budget.json and
         budget.md (docs/budget.md).
See docs/perf-regression.md.

options:
  -o, --out FILE|DIR     sweep, diff, ab: directory for the files (default: .), made if
                         missing; run: the results file (default: results.json);
                         compare: also write the comparison as JSON
  --device NAME|INDEX    Vulkan device (default: $LPV_DEVICE, else lavapipe)
  -q, --quiet            no progress bar or summary (compare, ab: the one-line verdict)
  -h, --help             this text
run, ab:
  --warmup N             untimed renders per case before the timed ones (default: the suite's)
run, ab, worker:
  --server-binary PATH   lpv-server for the server_round_trip cases, started on a free
                         loopback port (default: the lpv-server beside lpv-bench; in ab,
                         each build's own)
  --no-server            skip the server_round_trip cases instead
  --test-slowdown F      make every frame F times as slow (busy CPU; default 1): a known
                         regression, for testing the verdicts (bench/verdict-rates.sh)
run, sweep:
  --url URL              run: render every case through this lpv-server (POST /v1/render);
                         sweep: sweep through it (POST /v1/sweep); $LPV_SERVER_TOKEN is
                         sent as its bearer token
  -j, --jobs N           with --url, N requests at once, each on its own connection (default
                         1): run, N cases; sweep, N parts of the sweep. Behind a load
                         balancer, N replicas work together; the results have a serial run's
                         cases, images and rows, in its order
run:
  --repetitions N        timed renders per case (default: the suite's)
  --label NAME           the run's name in reports (default: the commit)
  --commit ID            the commit to record (default: the build's, or $LPV_BENCH_COMMIT)
run, compare, ab:
  --report FILE          also write a Markdown summary (for job summaries)
compare, ab:
  --alpha P              the ratios' intervals have confidence 1 - P (default: 0.01)
  --min-effect F         a change counts when its whole interval is beyond 1 +/- F
                         (default: 0.05 = 5%)
  --min-ms MS            smallest absolute change that counts (default: 0.1; on a real
                         GPU, whose passes take microseconds, use 0.005)
  --image-tolerance E    relative MSE of the thumbnails still "the same image" (default: 1e-4)
  --gate-passes          a pass slower is a regression too (default: only the frame's totals,
                         gpu_ms, wall_ms and round_trip_ms, are; passes are reported)
  --max-probe-spread F   a run whose CPU noise probe scattered more (MAD / median) gets no
                         verdict on its times: inconclusive, exit 4 (default: 0.05)
budget:
  --size N               the frames' width and height (default: 128)
  --samples N            the full sweeps' reference paths per pixel (default: 512)
ab:
  --a PATH, --b PATH     lpv-bench of the baseline (A) and of the candidate (B)
  --rounds N             pairs of timed renders per case (default: the suite's repetitions)

environment: LPV_DEVICE, LPV_PIPELINE_CACHE (a file, or "off"), LPV_BENCH_COMMIT,
             LPV_SERVER_TOKEN
exit status: 0 success (compare, ab: no regression); 1 failure (device, files, a case
             that failed; compare, ab: a total slower (or a pass, with --gate-passes), an
             image changed, a case failing in the candidate, or no case compared at all);
             2 bad usage or bad input; 4 compare, ab: inconclusive, the machine was too
             noisy for a verdict on the times (docs/perf-regression.md)
suites in bench/suites: )" + (names.empty() ? "none found" : names) + "\n";
}

namespace {

constexpr unsigned bit(Command c) { return 1u << static_cast<unsigned>(c); }
constexpr unsigned kAll = bit(Command::sweep) | bit(Command::diff) | bit(Command::run) | bit(Command::compare) |
                          bit(Command::ab) | bit(Command::worker) | bit(Command::budget);
constexpr unsigned kSuites = bit(Command::run) | bit(Command::ab);
constexpr unsigned kLocalRuns = kSuites | bit(Command::worker);  // where this build renders
constexpr unsigned kVerdicts = bit(Command::compare) | bit(Command::ab);
constexpr unsigned kRenders = bit(Command::sweep) | bit(Command::diff) | kLocalRuns | bit(Command::budget);

const char* name_of(Command c) {
  switch (c) {
    case Command::sweep: return "sweep";
    case Command::diff: return "diff";
    case Command::run: return "run";
    case Command::compare: return "compare";
    case Command::ab: return "ab";
    case Command::worker: return "worker";
    case Command::budget: return "budget";
  }
  return "?";
}

template <class T>
std::string text_of(T x) {
  std::ostringstream text;
  text << x;
  return text.str();
}

template <class T>
T number(const std::string& option, const std::string& text, T lo, T hi) {
  T value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || !(value >= lo) || !(value <= hi))
    throw UsageError(option + " must be a number in [" + text_of(lo) + ", " + text_of(hi) + "], got '" +
                     text + "'");
  return value;
}

struct Flag {
  std::string_view name;
  std::string_view alias;
  unsigned commands;
  std::function<void(Options&, const std::string& value)> set;  // a switch gets ""
  bool takes_value = true;
};

const std::vector<Flag>& flags() {
  using S = const std::string&;
  static const std::vector<Flag> table = {
      {"--out", "-o", kAll & ~bit(Command::worker), [](Options& o, S v) { o.out = v; }},
      {"--device", "", kRenders, [](Options& o, S v) { o.device = v; }},
      {"--quiet", "-q", kAll, [](Options& o, S) { o.quiet = true; }, false},
      {"--url", "", bit(Command::run) | bit(Command::sweep), [](Options& o, S v) { o.url = v; }},
      {"--jobs", "-j", bit(Command::run) | bit(Command::sweep),
       [](Options& o, S v) { o.jobs = number<std::uint32_t>("--jobs", v, 1, 64); }},
      {"--repetitions", "", bit(Command::run),
       [](Options& o, S v) { o.repetitions = number<std::uint32_t>("--repetitions", v, 1, 1000); }},
      {"--warmup", "", kSuites, [](Options& o, S v) { o.warmup = number<std::uint32_t>("--warmup", v, 0, 100); }},
      {"--report", "", bit(Command::run) | kVerdicts, [](Options& o, S v) { o.report = v; }},
      {"--label", "", bit(Command::run), [](Options& o, S v) { o.label = v; }},
      {"--commit", "", bit(Command::run), [](Options& o, S v) { o.commit = v; }},
      {"--server-binary", "", kLocalRuns, [](Options& o, S v) { o.server_binary = v; }},
      {"--no-server", "", kLocalRuns, [](Options& o, S) { o.no_server = true; }, false},
      {"--test-slowdown", "", kLocalRuns,
       [](Options& o, S v) { o.test_slowdown = number<double>("--test-slowdown", v, 1.0, 10.0); }},
      {"--alpha", "", kVerdicts,
       [](Options& o, S v) { o.compare.thresholds.alpha = number<double>("--alpha", v, 1e-9, 0.5); }},
      {"--min-effect", "", kVerdicts,
       [](Options& o, S v) { o.compare.thresholds.min_effect = number<double>("--min-effect", v, 0.0, 10.0); }},
      {"--min-ms", "", kVerdicts,
       [](Options& o, S v) { o.compare.thresholds.min_ms = number<double>("--min-ms", v, 0.0, 1e6); }},
      {"--image-tolerance", "", kVerdicts,
       [](Options& o, S v) { o.compare.image_tolerance = number<double>("--image-tolerance", v, 0.0, 1e6); }},
      {"--gate-passes", "", kVerdicts, [](Options& o, S) { o.compare.gate_passes = true; }, false},
      {"--max-probe-spread", "", kVerdicts,
       [](Options& o, S v) { o.compare.max_probe_spread = number<double>("--max-probe-spread", v, 0.0, 1e6); }},
      {"--a", "", bit(Command::ab), [](Options& o, S v) { o.build_a = v; }},
      {"--b", "", bit(Command::ab), [](Options& o, S v) { o.build_b = v; }},
      {"--rounds", "", bit(Command::ab), [](Options& o, S v) { o.rounds = number<std::uint32_t>("--rounds", v, 1, 1000); }},
      {"--size", "", bit(Command::budget), [](Options& o, S v) { o.size = number<std::uint32_t>("--size", v, 16, 2048); }},
      {"--samples", "", bit(Command::budget),
       [](Options& o, S v) { o.reference_samples = number<std::uint32_t>("--samples", v, 1, 65536); }},
  };
  return table;
}

Command command_named(const std::string& name) {
  for (const Command c : {Command::sweep, Command::diff, Command::run, Command::compare, Command::ab, Command::worker,
                          Command::budget})
    if (name == name_of(c)) return c;
  throw UsageError("unknown command '" + name + "' (sweep, diff, run, compare, ab, worker or budget)");
}

// The positional arguments each command takes, and what they are.
void check_inputs(const Options& o) {
  if (o.command == Command::budget) return;  // any number of scenes
  const std::size_t wanted = o.command == Command::compare ? 2 : 1;
  if (o.inputs.size() < wanted) {
    switch (o.command) {
      case Command::sweep:
      case Command::diff: throw UsageError("missing the request file (or - for standard input)");
      case Command::run:
      case Command::ab:
      case Command::worker: throw UsageError("missing the suite (a file, or a name in bench/suites)");
      case Command::compare: throw UsageError("compare needs two results files: BASELINE.json CANDIDATE.json");
      case Command::budget: break;  // returned above
    }
  }
  if (o.inputs.size() > wanted) throw UsageError("unexpected argument '" + o.inputs[wanted] + "'");
  if (o.jobs > 1 && !o.url)
    throw UsageError("--jobs needs --url: in this process one device renders one thing at a time");
  if (o.command == Command::ab && (!o.build_a || !o.build_b))
    throw UsageError("ab needs both builds: --a PATH_TO_LPV_BENCH_A --b PATH_TO_LPV_BENCH_B");
}

}  // namespace

Options parse(int argc, char** argv) {
  Options o;
  std::optional<Command> command;
  // Options are checked against the command once it is known (it may come after them).
  std::vector<std::pair<const Flag*, std::string>> given;
  for (const auto& item : core::walk_command_line<UsageError>(argc, argv, flags())) {
    using Kind = core::CommandLineItem<Flag>::Kind;
    if (item.kind == Kind::help) {
      o.help = true;
      return o;
    }
    if (item.kind == Kind::option)
      given.emplace_back(item.option, item.value);
    else if (!command)
      command = command_named(item.value);
    else
      o.inputs.push_back(item.value);
  }
  if (!command) throw UsageError("missing the command (sweep, diff, run, compare, ab, worker or budget)");
  o.command = *command;
  for (const auto& [flag, value] : given) {
    if (!(flag->commands & bit(o.command)))
      throw UsageError("option " + std::string(flag->name) + " is not for " + name_of(o.command));
    flag->set(o, value);
  }
  check_inputs(o);
  return o;
}

}  // namespace bench
