// lpv-render: one request in, one image file (and optionally stats) out.
#include "api/counted.hpp"
#include "api/request_error.hpp"
#include "api/request_json.hpp"
#include "cli_options.hpp"
#include "core/elapsed.hpp"
#include "image/file_io.hpp"
#include "lab/accuracy/budget.hpp"
#include "lab/accuracy/workbench.hpp"
#include "renderer/gpu_device.hpp"
#include "renderer/output.hpp"
#include "renderer/renderer.hpp"
#include "scene/builtin_scenes.hpp"
#include "scene/gltf_loader.hpp"
#include "tools/common/progress_bar.hpp"

#include <unistd.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <sstream>

namespace {

constexpr int kExitBadSceneFile = 3;

// A --scene file that cannot be loaded: "lpv-render: <path>: <message>", exit status 3.
class SceneFileError : public tools::InputError {
 public:
  SceneFileError(const std::string& path, const std::string& message)
      : tools::InputError(path + ": " + message, kExitBadSceneFile) {}
};

scene::Scene load_scene_file(const std::string& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) throw SceneFileError(path, "cannot read the scene file: no such file");
  if (!std::filesystem::is_regular_file(status)) throw SceneFileError(path, "cannot read the scene file: not a regular file");
  try {
    return scene::load_gltf_file(path);
  } catch (const scene::LoadError& e) {
    throw SceneFileError(path, e.what());
  }
}

std::string read_request_text(const std::string& file) {
  std::ostringstream text;
  if (file == "-") {
    text << std::cin.rdbuf();
    return text.str();
  }
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) throw cli::UsageError("cannot read request file '" + file + "': no such file");
  std::ifstream in(file, std::ios::binary);
  if (!in || std::filesystem::is_directory(file, ec)) throw cli::UsageError("cannot read request file '" + file + "'");
  text << in.rdbuf();
  return text.str();
}

// The format follows the request; an .exr or .pfm output name picks that format when the
// request left the default, and a name that contradicts an explicit format is an error. So
// is an extension no format has: "-o out.jpg" must not write a PNG under that name. A name
// without one (/dev/stdout) takes the request's format.
void reconcile_format(api::RenderRequest& request, const std::string& output_file, bool format_given) {
  std::string ext = std::filesystem::path(output_file).extension().string();
  if (ext.empty()) return;
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  constexpr api::ImageFormat kFormats[] = {api::ImageFormat::png, api::ImageFormat::exr, api::ImageFormat::pfm};
  const auto f = std::find_if(std::begin(kFormats), std::end(kFormats),
                              [&](api::ImageFormat f) { return ext == renderer::file_extension(f); });
  if (f == std::end(kFormats))
    throw cli::UsageError("cannot write '" + output_file + "': lpv-render writes .png, .exr and .pfm files");
  if (!format_given) request.output.format = *f;
  if (request.output.format != *f)
    throw cli::UsageError("output file '" + output_file + "' does not match the requested format '" +
                          api::to_string(request.output.format) + "'");
}

void print_summary(const api::RenderStats& s, const std::string& file) {
  std::fprintf(stderr, "%s: %ux%u %s, %s on %s\n", file.c_str(), s.width, s.height, s.view.c_str(),
               api::counted(s.frames, "frame").c_str(), s.device.c_str());
  std::fprintf(stderr, "  gpu %.3f ms (median):", s.gpu_ms.median);
  for (const auto& p : s.passes)
    if (p.ran) std::fprintf(stderr, " %s %.3f", p.name.c_str(), p.gpu_ms.median);
  std::fprintf(stderr, "\n  wall %.3f ms per frame, encode %.3f ms\n", s.wall_ms.median, s.cpu_ms.at("encode").median);
  if (s.budget)  // the plan's first decision says the choice: what, predicted, the runner-up
    std::fprintf(stderr, "  %s\n", s.decisions.front().c_str());
  for (const auto& warning : s.warnings) std::fprintf(stderr, "  warning: %s\n", warning.c_str());
}

int run(int argc, char** argv) {
  const cli::Options options = cli::parse(argc, argv);
  if (options.help) {
    std::fputs(cli::usage(), stdout);
    return 0;
  }
  if (options.list_scenes) {
    for (const auto& s : scene::builtin_scenes()) std::printf("%-20s %s\n", s.name.c_str(), s.description.c_str());
    return 0;
  }
  if (options.list_devices) {
    const auto devices = renderer::GpuDevice::enumerate();
    for (std::size_t i = 0; i < devices.size(); ++i)
      std::printf("[%zu] %s (%s)\n", i, devices[i].name.c_str(), devices[i].driver.c_str());
    return 0;
  }

  api::RenderRequest request;
  bool format_given = false;
  bool scene_given = false;
  if (options.request_file) {
    const std::string text = read_request_text(*options.request_file);
    request = api::parse_render_request(text);
    const auto json = nlohmann::json::parse(text);
    format_given = json.contains("output") && json["output"].contains("format");
    scene_given = json.contains("scene");
  }
  if (options.scene) request.scene = *options.scene;
  // A scene file is loaded before the device is made, so a bad file fails fast.
  std::optional<scene::Scene> file_scene;
  if (options.scene_file) {
    if (scene_given)
      throw cli::UsageError("the request names the scene '" + request.scene + "' and --scene names the file '" +
                            *options.scene_file + "': give one of them");
    file_scene = load_scene_file(*options.scene_file);
  }
  const std::string scene_name = file_scene ? file_scene->name : request.scene;
  const std::string output_file =
      options.output_file.value_or(scene_name + renderer::file_extension(request.output.format));
  reconcile_format(request, output_file, format_given);

  vkx::DeviceOptions device_options = vkx::DeviceOptions::from_environment();
  if (options.device) device_options.selector = *options.device;
  if (options.validation) device_options.validation = true;
  renderer::GpuDevice device(device_options);
  // Progress on a terminal, erased when the render is done: the summary stays, not the bar.
  const bool show_progress = !options.quiet && isatty(STDERR_FILENO) == 1;
  tools::ProgressBar bar(show_progress);
  renderer::RendererOptions renderer_options{.propagate_column = options.propagate_column};
  if (show_progress)
    renderer_options.progress = [&](const renderer::RenderProgress& p) {
      bar.update("render", p.done, "frame " + std::to_string(p.frame) + "/" + std::to_string(p.frames) + " " + p.pass);
    };
  // A budget measures its models with sweeps, which find the scene by name: a scene file is
  // then served under a name no built-in scene has.
  if (request.budget_ms && file_scene) {
    request.scene = "file:" + file_scene->name;
    renderer_options.scenes = [&](const std::string& name) -> std::optional<scene::Scene> {
      if (name == request.scene) return *file_scene;
      return std::nullopt;
    };
  }
  renderer::Renderer renderer(device.vulkan(), std::move(renderer_options));
  renderer::RenderResult result;
  if (request.budget_ms) {
    accuracy::Workbench bench(renderer);
    try {
      result = accuracy::render_within_budget(bench, request, renderer::readback_for(request.output));
    } catch (const scene::LoadError& e) {
      throw SceneFileError(options.scene_file.value_or(request.scene), e.what());
    }
  } else if (file_scene) {
    try {
      result = renderer.render(*file_scene, request, renderer::readback_for(request.output));
    } catch (const scene::LoadError& e) {
      throw SceneFileError(*options.scene_file, e.what());
    }
  } else {
    result = renderer.render(request);
  }
  bar.erase();

  if (request.dry_run) {  // the plan alone: its stats on standard output (or --stats), no image
    const std::string json = api::to_json(result.stats).dump(2) + "\n";
    if (options.stats_file && *options.stats_file != "-")
      image::write_file_atomically(*options.stats_file,
                                   std::span(reinterpret_cast<const std::uint8_t*>(json.data()), json.size()));
    else
      std::fputs(json.c_str(), stdout);
    return 0;
  }

  const auto encode_start = std::chrono::steady_clock::now();
  const std::vector<std::uint8_t> bytes = renderer::encode_output(result, request.output.format);
  const double encode_ms = core::ms_since(encode_start);
  result.stats.cpu_ms["encode"] = api::TimeSummary::of({encode_ms});
  image::write_file_atomically(output_file, bytes);

  if (options.stats_file) {
    const std::string json = api::to_json(result.stats).dump(2) + "\n";
    if (*options.stats_file == "-") {
      std::fputs(json.c_str(), stdout);
    } else {
      image::write_file_atomically(*options.stats_file,
                                   std::span(reinterpret_cast<const std::uint8_t*>(json.data()), json.size()));
    }
  }
  if (!options.quiet) print_summary(result.stats, output_file);
  if (device_options.validation && !device.validation_messages().empty()) {
    std::fprintf(stderr, "lpv-render: %s\n", api::counted(device.validation_messages().size(), "validation message").c_str());
    return tools::kExitFailure;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return tools::run_program("lpv-render", [&] { return run(argc, argv); });
}
