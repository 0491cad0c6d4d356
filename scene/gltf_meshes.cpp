// glTF triangle primitives into world-space scene geometry. Strips and fans are unrolled;
// missing normals are made flat (as the spec asks), unusable ones are replaced by the
// surface's; a mirroring transform reverses the winding so fronts stay counter-clockwise.
#include "api/counted.hpp"
#include "scene/gltf_accessors.hpp"
#include "scene/gltf_convert.hpp"

#include <glm/gtc/matrix_inverse.hpp>

#include <array>
#include <cmath>

namespace scene::gltf {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

const char* mode_name(int mode) {
  switch (mode) {
    case TINYGLTF_MODE_POINTS: return "POINTS";
    case TINYGLTF_MODE_LINE: return "LINES";
    case TINYGLTF_MODE_LINE_LOOP: return "LINE_LOOP";
    case TINYGLTF_MODE_LINE_STRIP: return "LINE_STRIP";
    default: return "unknown";
  }
}

std::size_t triangle_count(int mode, std::size_t indices) {
  if (mode == TINYGLTF_MODE_TRIANGLES) return indices / 3;
  return indices >= 3 ? indices - 2 : 0;  // strip or fan
}

std::vector<Triangle> assemble(int mode, const std::vector<std::uint32_t>& idx) {
  std::vector<Triangle> tris;
  tris.reserve(triangle_count(mode, idx.size()));
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    for (std::size_t i = 0; i + 2 < idx.size(); i += 3) tris.push_back({idx[i], idx[i + 1], idx[i + 2]});
  } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (std::size_t i = 0; i + 2 < idx.size(); ++i)
      tris.push_back(i % 2 == 0 ? Triangle{idx[i], idx[i + 1], idx[i + 2]} : Triangle{idx[i + 1], idx[i], idx[i + 2]});
  } else {  // fan around the first vertex
    for (std::size_t i = 1; i + 1 < idx.size(); ++i) tris.push_back({idx[0], idx[i], idx[i + 1]});
  }
  return tris;
}

glm::vec3 face_normal(const std::vector<Vertex>& v, const Triangle& t) {
  // Not normalised: its length is twice the area, the weight of an area-weighted mean.
  return glm::cross(v[t[1]].position - v[t[0]].position, v[t[2]].position - v[t[0]].position);
}

glm::vec3 unit_or(glm::vec3 v, glm::vec3 fallback) {
  const float length = glm::length(v);
  return std::isfinite(length) && length > 1e-30f ? v / length : fallback;
}

}  // namespace

void add_primitive(Conversion& c, int mesh_index, int primitive_index, const glm::dmat4& world) {
  const tinygltf::Primitive& p = c.model.meshes[std::size_t(mesh_index)].primitives[std::size_t(primitive_index)];
  const std::string what = "mesh " + std::to_string(mesh_index) + " primitive " + std::to_string(primitive_index);
  const int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
  if (mode <= TINYGLTF_MODE_LINE_STRIP)
    fail(LoadError::Kind::unsupported, what + ": mode " + mode_name(mode) + " (" + std::to_string(mode) +
                                           ") is not supported; only triangles, triangle strips and fans are");
  if (mode > TINYGLTF_MODE_TRIANGLE_FAN) invalid(what + ": mode " + std::to_string(mode) + " does not exist");

  const auto position = p.attributes.find("POSITION");
  if (position == p.attributes.end()) {
    c.warn(what + " has no POSITION: not drawn");
    return;
  }
  const std::size_t n = element_count(c.model, position->second, what + " POSITION");
  if (n > c.limits.max_vertices - std::min(c.limits.max_vertices, c.scene.vertices.size()))
    fail(LoadError::Kind::too_complex, "more than " + std::to_string(c.limits.max_vertices) + " vertices");
  const std::size_t index_count = p.indices >= 0 ? element_count(c.model, p.indices, what + " indices") : n;
  const std::size_t max_triangles = c.limits.max_triangles;
  if (triangle_count(mode, index_count) > max_triangles - std::min(max_triangles, c.scene.triangle_count()))
    fail(LoadError::Kind::too_complex, "more than " + std::to_string(max_triangles) + " triangles");

  const glm::dmat3 linear(world);
  const double det = glm::determinant(linear);
  if (!std::isfinite(det) || std::abs(det) < 1e-300) {
    c.warn(what + " is placed by a singular or non-finite transform: not drawn");
    return;
  }
  const glm::dmat3 normal_matrix = glm::inverseTranspose(linear);

  const std::vector<float> positions = read_floats(c.model, position->second, 3, what + " POSITION");
  std::vector<float> normals;
  if (const auto it = p.attributes.find("NORMAL"); it != p.attributes.end()) {
    normals = read_floats(c.model, it->second, 3, what + " NORMAL");
    if (normals.size() != positions.size()) invalid(what + ": NORMAL and POSITION counts differ");
  }
  std::vector<float> uvs;
  const int set = texcoord_set_of(c, p.material);
  if (set >= 0) {
    const std::string name = "TEXCOORD_" + std::to_string(set);
    if (const auto it = p.attributes.find(name); it != p.attributes.end()) {
      uvs = read_floats(c.model, it->second, 2, what + " " + name);
      if (uvs.size() / 2 != n) invalid(what + ": " + name + " and POSITION counts differ");
    } else {
      c.warn(what + " has no " + name + " for its texture: it reads texel (0, 0)");
    }
  }
  std::vector<std::uint32_t> indices;
  if (p.indices >= 0) {
    indices = read_indices(c.model, p.indices, what + " indices");
    for (std::uint32_t i : indices)
      if (i >= n)
        invalid(what + ": index " + std::to_string(i) + " is out of range (" + api::counted(n, "vertex", "vertices") + ")");
  } else {
    indices.resize(n);
    for (std::size_t i = 0; i < n; ++i) indices[i] = std::uint32_t(i);
  }
  std::vector<Triangle> triangles = assemble(mode, indices);
  if (det < 0.0)
    for (Triangle& t : triangles) std::swap(t[1], t[2]);

  std::vector<Vertex> vertices(n);
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3 local(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
    const glm::vec3 placed(glm::dvec3(world * glm::dvec4(local, 1.0)));
    if (!all_finite(placed)) invalid(what + ": POSITION has non-finite values");
    vertices[i].position = placed;
    if (!uvs.empty()) vertices[i].uv = glm::vec2(uvs[2 * i], uvs[2 * i + 1]);
    if (!all_finite(vertices[i].uv)) vertices[i].uv = glm::vec2(0.0f);
  }

  if (normals.empty()) {
    // Flat normals: every triangle gets its own three vertices.
    std::vector<Vertex> flat;
    flat.reserve(triangles.size() * 3);
    for (Triangle& t : triangles) {
      const glm::vec3 normal = unit_or(face_normal(vertices, t), glm::vec3(0.0f, 0.0f, 1.0f));
      for (std::uint32_t& corner : t) {
        flat.push_back(vertices[corner]);
        flat.back().normal = normal;
        corner = std::uint32_t(flat.size() - 1);
      }
    }
    vertices = std::move(flat);
  } else {
    std::vector<glm::vec3> surface(n, glm::vec3(0.0f));  // area-weighted face normals around each vertex
    for (const Triangle& t : triangles)
      for (std::uint32_t corner : t) surface[corner] += face_normal(vertices, t);
    std::size_t replaced = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const glm::dvec3 given(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]);
      const glm::vec3 placed(normal_matrix * given);
      const float length = glm::length(placed);
      if (std::isfinite(length) && length > 1e-30f) {
        vertices[i].normal = placed / length;
      } else {
        vertices[i].normal = unit_or(surface[i], glm::vec3(0.0f, 0.0f, 1.0f));
        ++replaced;
      }
    }
    if (replaced) c.warn(what + ": " + api::counted(replaced, "zero or non-finite normal") + " replaced by the surface's");
  }
  if (!p.targets.empty()) c.warn(what + ": morph targets are not supported: the base mesh is drawn");

  if (vertices.size() > c.limits.max_vertices - std::min(c.limits.max_vertices, c.scene.vertices.size()))
    fail(LoadError::Kind::too_complex, "more than " + std::to_string(c.limits.max_vertices) + " vertices");
  Draw draw;
  draw.first_index = std::uint32_t(c.scene.indices.size());
  draw.index_count = std::uint32_t(triangles.size() * 3);
  draw.material = material_for(c, p.material);
  const auto base = std::uint32_t(c.scene.vertices.size());
  c.scene.vertices.insert(c.scene.vertices.end(), vertices.begin(), vertices.end());
  for (const Triangle& t : triangles)
    for (std::uint32_t corner : t) c.scene.indices.push_back(base + corner);
  if (draw.index_count) c.scene.draws.push_back(draw);
}

}  // namespace scene::gltf
