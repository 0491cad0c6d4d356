// glTF parsing (tinygltf, with this loader's own file access and image decoding) and the
// conversion of the node hierarchy: meshes, KHR_lights_punctual lights and the camera.
#include "scene/gltf_loader.hpp"

#include "scene/gltf_convert.hpp"
#include "scene/gltf_precheck.hpp"
#include "scene/image_decode.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>

namespace scene {
namespace {

using gltf::all_finite;
using gltf::fail;
using gltf::invalid;

// What tinygltf's callbacks need: the options, the model being parsed, and what went wrong
// inside them.
struct ParseState {
  const LoadOptions& options;
  const tinygltf::Model& model;
  std::size_t texels = 0;
  std::string invalid;           // an image whose data lies outside its buffer
  std::string too_complex;       // an image over the texel budget
  std::string busy;              // an image the decode budget had no room for
  std::string refused_file;      // an external file that may not be read
  std::vector<std::string> image_warnings;
  std::vector<std::string> kept_smaller;  // images halved to what the renderer keeps
};

bool decode_image(tinygltf::Image* image, const int index, std::string* err, std::string*, int, int,
                  const unsigned char* bytes, int size, void* user) {
  auto& state = *static_cast<ParseState*>(user);
  const std::string what = "image " + std::to_string(index);
  if (image->bufferView >= 0) {
    // tinygltf checked that the view and its buffer exist, not that the view fits in the
    // buffer: `bytes` may reach past its end. (Buffers and views are parsed before images.)
    const tinygltf::BufferView& view = state.model.bufferViews[std::size_t(image->bufferView)];
    const std::size_t buffer = state.model.buffers[std::size_t(view.buffer)].data.size();
    if (view.byteOffset > buffer || view.byteLength > buffer - view.byteOffset) {
      state.invalid = what + ": its buffer view reaches past the end of its buffer";
      if (err) *err += state.invalid;
      return false;
    }
  }
  const LoadLimits& limits = state.options.limits;
  const DecodeLimits decode{limits.max_texels - std::min(limits.max_texels, state.texels), limits.max_texture_side,
                            limits.max_kept_texture_side, limits.decode_budget.get(), limits.decode_wait};
  DecodedImage decoded = decode_rgba8({bytes, std::size_t(std::max(size, 0))}, decode);
  if (decoded.over_limit) {
    state.too_complex = what + ": " + decoded.error + " (over all images)";
    if (err) *err += state.too_complex;
    return false;
  }
  if (decoded.busy) {
    state.busy = what + ": " + decoded.error;
    if (err) *err += state.busy;
    return false;
  }
  if (!decoded.error.empty()) {  // an unreadable texture is dropped, not the scene
    state.image_warnings.push_back(what + ": " + decoded.error);
    return true;
  }
  state.texels += std::size_t(decoded.decoded_width) * decoded.decoded_height;
  if (decoded.width != decoded.decoded_width || decoded.height != decoded.decoded_height)
    state.kept_smaller.push_back(what + ": " + std::to_string(decoded.decoded_width) + "x" +
                                 std::to_string(decoded.decoded_height) + " kept at " + std::to_string(decoded.width) +
                                 "x" + std::to_string(decoded.height) + " (textures are kept up to " +
                                 std::to_string(limits.max_kept_texture_side) + " texels per side)");
  image->width = int(decoded.width);
  image->height = int(decoded.height);
  image->component = 4;
  image->bits = 8;
  image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  image->image = std::move(decoded.rgba);
  return true;
}

// The path of an external file if it lies inside the allowed directory; empty otherwise.
std::filesystem::path allowed_path(const ParseState& state, const std::string& path) {
  const std::filesystem::path& dir = state.options.external_files_dir;
  if (dir.empty()) return {};
  std::error_code ec;
  const std::filesystem::path root = std::filesystem::weakly_canonical(dir, ec);
  if (ec) return {};
  const std::filesystem::path file = std::filesystem::weakly_canonical(path, ec);
  if (ec) return {};
  const auto [r, f] = std::mismatch(root.begin(), root.end(), file.begin(), file.end());
  return r == root.end() ? file : std::filesystem::path{};
}

bool file_exists(const std::string& path, void* user) {
  auto& state = *static_cast<ParseState*>(user);
  const std::filesystem::path file = allowed_path(state, path);
  if (file.empty() && state.refused_file.empty()) state.refused_file = path;
  std::error_code ec;
  return !file.empty() && std::filesystem::is_regular_file(file, ec);
}

std::string expand_path(const std::string& path, void*) { return path; }

bool read_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  auto& state = *static_cast<ParseState*>(user);
  const std::filesystem::path file = allowed_path(state, path);
  if (file.empty()) {
    if (state.refused_file.empty()) state.refused_file = path;
    if (err) *err += "external file '" + path + "' may not be read\n";
    return false;
  }
  std::ifstream in(file, std::ios::binary);
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  if (!in || ec || size > (std::uintmax_t(1) << 31)) {
    if (err) *err += "cannot read '" + path + "'\n";
    return false;
  }
  out->resize(std::size_t(size));
  in.read(reinterpret_cast<char*>(out->data()), std::streamsize(size));
  return bool(in);
}

bool write_file(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "the loader writes no files\n";
  return false;
}

// tinygltf's error text, one line, bounded.
std::string first_lines(const std::string& text) {
  std::string out;
  for (char ch : text) out += (ch == '\n' || ch == '\r') ? ' ' : ch;
  while (!out.empty() && out.back() == ' ') out.pop_back();
  if (out.size() > 300) out = out.substr(0, 300) + "...";
  return out.empty() ? "unknown error" : out;
}

tinygltf::Model parse(std::span<const std::uint8_t> bytes, const LoadOptions& options, std::vector<std::string>& warnings) {
  if (bytes.size() > std::numeric_limits<unsigned int>::max()) fail(LoadError::Kind::too_complex, "file over 4 GiB");
  gltf::check_declarations(bytes);
  tinygltf::Model model;
  ParseState state{options, model};
  tinygltf::TinyGLTF parser;
  parser.SetImageLoader(decode_image, &state);
  parser.SetFsCallbacks({file_exists, expand_path, read_file, write_file, &state});
  std::string err, warn;
  const std::string base_dir = options.external_files_dir.string();
  const bool binary = bytes.size() >= 4 && std::equal(bytes.begin(), bytes.begin() + 4, "glTF");
  bool ok = false;
  try {
    ok = binary ? parser.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), base_dir)
                : parser.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                             unsigned(bytes.size()), base_dir);
  } catch (const std::exception& e) {
    invalid(std::string("not valid glTF: ") + e.what());
  }
  if (!state.too_complex.empty()) fail(LoadError::Kind::too_complex, state.too_complex);
  if (!state.busy.empty()) fail(LoadError::Kind::busy, state.busy);
  if (!state.invalid.empty()) invalid(state.invalid);
  if (!state.refused_file.empty())
    invalid(options.external_files_dir.empty()
                ? "the file refers to an external file ('" + state.refused_file +
                      "'): uploaded scenes must embed their buffers and images (.glb or data: URIs)"
                : "external file '" + state.refused_file + "' is missing or outside the scene's directory");
  if (!ok) invalid((binary ? "not valid glTF binary: " : "not valid glTF: ") + first_lines(err));
  for (const std::string& w : state.image_warnings) warnings.push_back(w + ": textures using it are ignored");
  for (const std::string& w : state.kept_smaller) warnings.push_back(w);
  return model;
}

// Required extensions were checked before parsing (check_declarations); those only used
// may be ignored, with a word.
void warn_unsupported_extensions(const tinygltf::Model& model, gltf::Conversion& c) {
  for (const std::string& ext : model.extensionsUsed)
    if (!gltf::supported_extension(ext)) c.warn("extension " + ext + " is not supported: ignored");
}

bool finite(const std::vector<double>& values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

glm::dmat4 local_transform(const tinygltf::Node& node, int index) {
  const std::string what = "node " + std::to_string(index);
  if (!finite(node.matrix) || !finite(node.translation) || !finite(node.rotation) || !finite(node.scale))
    invalid(what + ": its transform has non-finite values");
  if (!node.matrix.empty()) {
    if (node.matrix.size() != 16) invalid(what + ": matrix must have 16 numbers");
    glm::dmat4 m;
    for (int col = 0; col < 4; ++col)
      for (int row = 0; row < 4; ++row) m[col][row] = node.matrix[std::size_t(col * 4 + row)];
    return m;
  }
  glm::dmat4 m(1.0);
  if (!node.translation.empty()) {
    if (node.translation.size() != 3) invalid(what + ": translation must have 3 numbers");
    m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
  }
  if (!node.rotation.empty()) {
    if (node.rotation.size() != 4) invalid(what + ": rotation must have 4 numbers");
    glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);  // w, x, y, z
    const double length = glm::length(q);
    if (!(length > 0.0)) invalid(what + ": rotation is a zero quaternion");
    m *= glm::mat4_cast(q / length);
  }
  if (!node.scale.empty()) {
    if (node.scale.size() != 3) invalid(what + ": scale must have 3 numbers");
    m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
  }
  return m;
}

float degrees(double radians) { return float(radians * 180.0 / 3.14159265358979323846); }

// A KHR_lights_punctual light placed by its node: at the node's origin, shining down its -Z.
void add_light(gltf::Conversion& c, int index, const glm::dmat4& world) {
  const std::string what = "light " + std::to_string(index);
  if (index < 0 || std::size_t(index) >= c.model.lights.size()) invalid(what + " does not exist");
  const tinygltf::Light& gl = c.model.lights[std::size_t(index)];
  api::Light light;
  if (gl.type == "point") light.type = api::LightType::point;
  else if (gl.type == "spot") light.type = api::LightType::spot;
  else if (gl.type == "directional") light.type = api::LightType::directional;
  else invalid(what + ": type '" + gl.type + "' is not point, spot or directional");
  if (!gl.color.empty()) {
    if (gl.color.size() != 3 || !finite(gl.color) || *std::min_element(gl.color.begin(), gl.color.end()) < 0.0)
      invalid(what + ": color must be 3 finite numbers >= 0");
    light.color = glm::vec3(float(gl.color[0]), float(gl.color[1]), float(gl.color[2]));
  }
  if (!std::isfinite(gl.intensity) || gl.intensity < 0.0 || gl.intensity > api::limits::max_intensity)
    invalid(what + ": intensity must be a finite number in [0, " + std::to_string(api::limits::max_intensity) + "]");
  light.intensity = float(gl.intensity);
  if (!std::isfinite(gl.range) || gl.range < 0.0) invalid(what + ": range must be a finite number >= 0");
  light.range = float(gl.range);
  if (light.type == api::LightType::spot) {
    const double inner = gl.spot.innerConeAngle, outer = gl.spot.outerConeAngle;
    if (!std::isfinite(inner) || !std::isfinite(outer) ||
        !api::spot_cones_valid(inner, outer, 3.14159265358979323846 / 2.0 + 1e-9))
      invalid(what + ": spot cone angles need 0 <= innerConeAngle < outerConeAngle <= pi/2");
    light.inner_cone_deg = degrees(inner);
    light.outer_cone_deg = std::min(degrees(outer), 90.0f);
  }
  light.position = glm::vec3(world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
  const glm::dvec3 direction = glm::dmat3(world) * glm::dvec3(0.0, 0.0, -1.0);
  const double length = glm::length(direction);
  if (!(length > 0.0) || !std::isfinite(length) || !all_finite(light.position)) {
    c.warn(what + " is placed by a singular transform: ignored");
    return;
  }
  light.direction = glm::vec3(direction / length);
  if (c.scene.lights.size() >= api::limits::max_lights)
    fail(LoadError::Kind::too_complex, "more than " + std::to_string(api::limits::max_lights) + " lights");
  c.scene.lights.push_back(light);
}

// The first perspective camera of the hierarchy becomes the default camera.
bool take_camera(gltf::Conversion& c, int index, const glm::dmat4& world) {
  const std::string what = "camera " + std::to_string(index);
  if (index < 0 || std::size_t(index) >= c.model.cameras.size()) invalid(what + " does not exist");
  const tinygltf::Camera& gc = c.model.cameras[std::size_t(index)];
  if (gc.type != "perspective") {
    c.warn(what + ": only perspective cameras are supported: ignored");
    return false;
  }
  const tinygltf::PerspectiveCamera& p = gc.perspective;
  const float fov = degrees(p.yfov);
  if (!(fov >= api::limits::min_fov_y_deg && fov <= api::limits::max_fov_y_deg) || !std::isfinite(p.znear) ||
      p.znear < 0.0 || !std::isfinite(p.zfar) || p.zfar < 0.0 || (p.zfar > 0.0 && p.zfar <= p.znear)) {
    c.warn(what + ": yfov, znear or zfar out of range: ignored");
    return false;
  }
  const glm::dvec3 position(world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
  const glm::dvec3 forward = glm::dmat3(world) * glm::dvec3(0.0, 0.0, -1.0);
  const glm::dvec3 up = glm::dmat3(world) * glm::dvec3(0.0, 1.0, 0.0);
  const double sine = glm::length(glm::cross(glm::normalize(forward), glm::normalize(up)));
  if (!all_finite(position) || !(glm::length(forward) > 0.0) || !(sine > 1e-3)) {
    c.warn(what + " is placed by a degenerate transform: ignored");
    return false;
  }
  api::Camera camera;
  camera.position = glm::vec3(position);
  camera.target = glm::vec3(position + glm::normalize(forward));
  camera.up = glm::vec3(glm::normalize(up));
  camera.fov_y_deg = fov;
  camera.near = float(p.znear);
  camera.far = float(p.zfar);
  c.scene.camera = camera;
  return true;
}

// The nodes to draw: the default scene's (or the first's); without scenes, every root node.
std::vector<int> root_nodes(gltf::Conversion& c) {
  const tinygltf::Model& m = c.model;
  if (!m.scenes.empty()) {
    const int s = m.defaultScene >= 0 ? m.defaultScene : 0;
    if (std::size_t(s) >= m.scenes.size()) invalid("the default scene " + std::to_string(s) + " does not exist");
    return m.scenes[std::size_t(s)].nodes;
  }
  c.warn("the file has no scene: all root nodes are drawn");
  std::vector<bool> is_child(m.nodes.size(), false);
  for (const tinygltf::Node& node : m.nodes)
    for (int child : node.children)
      if (child >= 0 && std::size_t(child) < m.nodes.size()) is_child[std::size_t(child)] = true;
  std::vector<int> roots;
  for (std::size_t i = 0; i < m.nodes.size(); ++i)
    if (!is_child[i]) roots.push_back(int(i));
  return roots;
}

// Walks the hierarchy depth first without recursion (a file can nest nodes arbitrarily
// deep). The spec makes it a forest: a node reached twice, by a cycle or by two parents, is
// an error rather than an unbounded expansion. Returns whether a camera was found.
bool convert_nodes(gltf::Conversion& c) {
  const tinygltf::Model& m = c.model;
  if (m.nodes.size() > c.limits.max_node_instances)
    fail(LoadError::Kind::too_complex, "more than " + std::to_string(c.limits.max_node_instances) + " nodes");
  std::vector<bool> visited(m.nodes.size(), false);
  struct Pending {
    int node;
    glm::dmat4 parent;
  };
  std::vector<Pending> stack;
  const std::vector<int> roots = root_nodes(c);
  for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, glm::dmat4(1.0)});
  bool has_camera = false;
  while (!stack.empty()) {
    const Pending p = stack.back();
    stack.pop_back();
    if (p.node < 0 || std::size_t(p.node) >= m.nodes.size()) invalid("node " + std::to_string(p.node) + " does not exist");
    if (visited[std::size_t(p.node)])
      invalid("node " + std::to_string(p.node) + " appears twice in the hierarchy (a cycle, or two parents)");
    visited[std::size_t(p.node)] = true;
    const tinygltf::Node& node = m.nodes[std::size_t(p.node)];
    const glm::dmat4 world = p.parent * local_transform(node, p.node);

    if (node.mesh >= 0) {
      if (std::size_t(node.mesh) >= m.meshes.size())
        invalid("node " + std::to_string(p.node) + ": mesh " + std::to_string(node.mesh) + " does not exist");
      for (std::size_t k = 0; k < m.meshes[std::size_t(node.mesh)].primitives.size(); ++k)
        gltf::add_primitive(c, node.mesh, int(k), world);
    }
    if (node.skin >= 0) c.warn("skins are not supported: skinned meshes are drawn in their bind pose");
    if (node.camera >= 0 && !has_camera) has_camera = take_camera(c, node.camera, world);
    if (const auto ext = node.extensions.find("KHR_lights_punctual"); ext != node.extensions.end()) {
      const tinygltf::Value& light = ext->second.Get("light");
      if (!light.IsNumber()) invalid("node " + std::to_string(p.node) + ": KHR_lights_punctual.light must be an index");
      add_light(c, light.GetNumberAsInt(), world);
    }
    for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) stack.push_back({*child, world});
  }
  if (!m.animations.empty()) c.warn("animations are not supported: the scene is drawn at rest");
  return has_camera;
}

// A camera that sees the whole scene: from the front (+Z) and a little above, as glTF
// viewers do, with the bounding sphere filling the vertical field of view.
api::Camera framing_camera(const Bounds& bounds) {
  api::Camera camera;
  camera.fov_y_deg = 40.0f;
  const glm::vec3 center = bounds.center();
  const float radius = std::max(bounds.radius(), 1e-3f);
  const float distance = radius / std::sin(glm::radians(camera.fov_y_deg) * 0.5f) * 1.05f;
  camera.target = center;
  camera.position = center + distance * glm::normalize(glm::vec3(0.0f, 0.35f, 1.0f));
  camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
  return camera;
}

bool emits(const Scene& s) {
  return std::any_of(s.materials.begin(), s.materials.end(),
                     [](const Material& m) { return glm::any(glm::greaterThan(m.emissive, glm::vec3(0.0f))); });
}

}  // namespace

Scene load_gltf(std::span<const std::uint8_t> bytes, const LoadOptions& options) {
  Scene scene;
  scene.name = options.name;
  const tinygltf::Model model = parse(bytes, options, scene.warnings);
  gltf::Conversion c{model, options.limits, scene, {}, {}, {}};
  for (const std::string& w : scene.warnings) c.warned.insert(w);
  warn_unsupported_extensions(model, c);
  const bool has_camera = convert_nodes(c);
  scene.update_bounds();
  if (!has_camera) scene.camera = framing_camera(scene.bounds);
  if (scene.lights.empty() && !emits(scene)) {
    // A file without lights would render black; a sun from above-front makes it visible,
    // and the warning says so. E = pi W/m^2: a white surface facing it has radiance 1.
    api::Light sun;
    sun.type = api::LightType::directional;
    sun.direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.5f));
    sun.intensity = 3.14159265f;
    scene.lights.push_back(sun);
    c.warn("the file has no lights: a directional light was added (replace it with the request's \"lights\")");
  }
  return scene;
}

Scene load_gltf_file(const std::filesystem::path& path, const LoadLimits& limits) {
  std::ifstream in(path, std::ios::binary);
  std::error_code ec;
  if (!in || std::filesystem::is_directory(path, ec)) invalid("cannot open '" + path.string() + "'");
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  LoadOptions options;
  options.name = path.stem().string();
  options.external_files_dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  options.limits = limits;
  return load_gltf(bytes, options);
}

}  // namespace scene
