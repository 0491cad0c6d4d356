// lpv-bench: accuracy against time and performance regressions from the command line.
// `sweep` and `diff` do what POST /v1/sweep and POST /v1/compare do, on a device of their
// own, and write files; `run`, `compare` and `ab` time benchmark suites and judge the
// differences (commands.hpp).
#include "api/accuracy_report.hpp"
#include "api/accuracy_request.hpp"
#include "api/request_error.hpp"
#include "api/request_json.hpp"
#include "bench_options.hpp"
#include "commands.hpp"
#include "http_sweep.hpp"
#include "image/exr.hpp"
#include "image/file_io.hpp"
#include "image/png.hpp"
#include "input_files.hpp"
#include "lab.hpp"
#include "lab/accuracy/compare.hpp"
#include "lab/accuracy/sweep.hpp"
#include "renderer/renderer.hpp"
#include "sweep_markdown.hpp"
#include "tools/common/program_main.hpp"
#include "tools/common/progress_bar.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace {


// A request file, or standard input for "-".
std::string read_request_text(const std::string& file) {
  if (file != "-") return bench::read_text_file(file);
  std::ostringstream text;
  text << std::cin.rdbuf();
  return text.str();
}

// On this machine's device, with the progress of each stage.
accuracy::SweepResult sweep_here(const bench::Options& options, const api::SweepRequest& request) {
  const std::size_t total = api::sweep_configurations(request).size();
  bench::Lab lab(options);
  tools::ProgressBar bar(!options.quiet);
  accuracy::SweepObserver observer;
  observer.reference_progress = [&](double fraction) {
    bar.update("reference", fraction, std::to_string(request.reference.samples) + " spp");
  };
  observer.row_measured = [&](std::size_t index, std::size_t, const api::SweepRow&) {
    bar.update("errors", double(index + 1) / double(total),
               "row " + std::to_string(index + 1) + "/" + std::to_string(total));
  };
  observer.timing_progress = [&](std::size_t done, std::size_t frames) {
    bar.update("timing", double(done) / double(frames),
               "frame " + std::to_string(done) + "/" + std::to_string(frames) + ", rows interleaved");
  };
  accuracy::SweepResult result = accuracy::sweep(lab.bench, request, observer);
  bar.finish();
  return result;
}

// Through a running server, in --jobs parts at once.
accuracy::SweepResult sweep_through_server(const bench::Options& options, const std::string& text) {
  tools::ProgressBar bar(!options.quiet);
  bar.update("sweep", 0.0, "through " + *options.url);
  accuracy::SweepResult result =
      bench::sweep_through(*options.url, nlohmann::json::parse(text), options.jobs, [&](std::size_t done, std::size_t parts) {
        bar.update("sweep", double(done) / double(parts),
                   std::to_string(done) + "/" + std::to_string(parts) + " parts through " + *options.url);
      });
  bar.finish();
  return result;
}

int run_sweep(const bench::Options& options, const std::string& text) {
  const api::SweepRequest request = api::parse_sweep_request(text);
  const accuracy::SweepResult result = options.url ? sweep_through_server(options, text) : sweep_here(options, request);

  const std::filesystem::path dir = options.out.value_or(".");
  std::filesystem::create_directories(dir);
  nlohmann::json json = {{"complete", result.complete},
                         {"reference", api::to_json(result.reference)},
                         {"table", api::to_json(result.table)},
                         {"request", nlohmann::json::parse(text)}};
  bench::write_text_file(dir / "sweep.json", json.dump(2) + "\n");
  bench::write_text_file(dir / "sweep.csv", api::to_csv(result.table));
  const std::string markdown = bench::sweep_markdown(result.table, result.reference);
  bench::write_text_file(dir / "sweep.md", markdown);
  bench::write_text_file(dir / "sweep.svg", api::to_svg_plot(result.table, api::sweep_plot_title(request.base.scene)));
  if (!options.quiet) std::fputs(markdown.c_str(), stdout);
  return 0;
}

int run_diff(const bench::Options& options, const std::string& text) {
  const api::CompareRequest request = api::parse_compare_request(text);
  bench::Lab lab(options);
  tools::ProgressBar bar(!options.quiet && request.reference.has_value());
  const accuracy::Comparison c =
      accuracy::compare(lab.bench, request, [&](double fraction) { bar.update("reference", fraction); });
  bar.finish();

  const std::filesystem::path dir = options.out.value_or(".");
  std::filesystem::create_directories(dir);
  image::write_file_atomically(dir / "base.png", image::encode_png(c.base.display));
  image::write_file_atomically(dir / "other.png", image::encode_png(c.other.display));
  image::write_file_atomically(dir / "difference.png", image::encode_png(c.difference.image));
  image::write_file_atomically(dir / "base.exr", image::encode_exr(c.base.final_image));
  image::write_file_atomically(dir / "other.exr", image::encode_exr(c.other.final_image));
  nlohmann::json json = {{"mask", api::to_string(c.mask)},
                         {"metrics", {{"final", api::to_json(c.final_error)}, {"indirect", api::to_json(c.indirect_error)}}},
                         {"difference_scale", c.difference.scale},
                         {"other", c.other.label}};
  if (c.base.stats) json["base_stats"] = api::to_json(*c.base.stats);
  if (c.other.stats) json["other_stats"] = api::to_json(*c.other.stats);
  if (c.other.reference) json["reference"] = api::to_json(*c.other.reference);
  bench::write_text_file(dir / "compare.json", json.dump(2) + "\n");
  if (!options.quiet) {
    std::printf("base against %s (%s pixels: %llu)\n", c.other.label.c_str(), api::to_string(c.mask).c_str(),
                static_cast<unsigned long long>(c.final_error.pixels));
    for (const auto& [name, m] : {std::pair{"final", c.final_error}, std::pair{"indirect", c.indirect_error}})
      std::printf("  %-8s RMSE %.4g  rel. MSE %.4g  PSNR %.2f dB  SSIM %.4f  bias %+.4g  max %.4g\n", name, m.rmse,
                  m.relative_mse, m.psnr_db, m.ssim, m.mean_signed_error, m.max_abs_error);
    if (c.base.stats) std::printf("  base: %.2f ms GPU per frame\n", c.base.stats->gpu_ms.median);
    if (c.other.stats) std::printf("  other: %.2f ms GPU per frame\n", c.other.stats->gpu_ms.median);
    if (c.other.reference)
      std::printf("  reference: %u spp, %.0f ms, noise RMSE %.3g\n", c.other.reference->settings.samples,
                  c.other.reference->build_ms + c.other.reference->trace_ms, c.other.reference->noise_rmse);
  }
  return 0;
}

int run(int argc, char** argv) {
  const bench::Options options = bench::parse(argc, argv);
  if (options.help) {
    std::fputs(bench::usage(bench::suite_names()).c_str(), stdout);
    return 0;
  }
  switch (options.command) {
    case bench::Command::run: return bench::run_command(options);
    case bench::Command::compare: return bench::compare_command(options);
    case bench::Command::ab: return bench::ab_command(options);
    case bench::Command::worker: return bench::worker_command(options);
    case bench::Command::budget: return bench::budget_command(options);
    case bench::Command::sweep: return run_sweep(options, read_request_text(options.inputs[0]));
    case bench::Command::diff: return run_diff(options, read_request_text(options.inputs[0]));
  }
  return tools::kExitFailure;
}

}  // namespace

int main(int argc, char** argv) {
  return tools::run_program("lpv-bench", [&] { return run(argc, argv); });
}
