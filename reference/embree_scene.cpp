#include "reference/embree_scene.hpp"

#include <embree3/rtcore.h>

#include <cstring>
#include <stdexcept>
#include <string>

namespace reference {
namespace {

const char* error_name(RTCError code) {
  switch (code) {
    case RTC_ERROR_NONE:
      return "RTC_ERROR_NONE";
    case RTC_ERROR_UNKNOWN:
      return "RTC_ERROR_UNKNOWN";
    case RTC_ERROR_INVALID_ARGUMENT:
      return "RTC_ERROR_INVALID_ARGUMENT";
    case RTC_ERROR_INVALID_OPERATION:
      return "RTC_ERROR_INVALID_OPERATION";
    case RTC_ERROR_OUT_OF_MEMORY:
      return "RTC_ERROR_OUT_OF_MEMORY";
    case RTC_ERROR_UNSUPPORTED_CPU:
      return "RTC_ERROR_UNSUPPORTED_CPU";
    case RTC_ERROR_CANCELLED:
      return "RTC_ERROR_CANCELLED";
  }
  return "unknown RTCError";
}

// An intersection context that carries the per-triangle cull table to the filter function.
// Embree hands the filter the context pointer it was given, so the extension is found again
// by a cast; `base` must stay the first member.
struct CullContext {
  RTCIntersectContext base;
  const glm::vec4* faces;  // xyz: the triangle's front normal (counter-clockwise), w: 1 if cullable
};

// Rejects hits on the back face of a cullable triangle, so the ray goes on to what lies behind.
void reject_back_faces(const RTCFilterFunctionNArguments* args) {
  const auto* context = reinterpret_cast<const CullContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const glm::vec4 face = context->faces[RTCHitN_primID(args->hit, args->N, i)];
    const glm::vec3 dir(RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i),
                        RTCRayN_dir_z(args->ray, args->N, i));
    if (face.w != 0.0f && glm::dot(glm::vec3(face), dir) >= 0.0f) args->valid[i] = 0;
  }
}

RTCRay make_ray(glm::vec3 origin, glm::vec3 direction, float t_far) {
  RTCRay ray{};
  ray.org_x = origin.x, ray.org_y = origin.y, ray.org_z = origin.z;
  ray.dir_x = direction.x, ray.dir_y = direction.y, ray.dir_z = direction.z;
  ray.tnear = 0.0f;
  ray.tfar = t_far;
  ray.mask = 0xffffffffu;
  return ray;
}

}  // namespace

struct EmbreeScene::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;  // null when there are no triangles
  std::vector<glm::vec4> faces;
  std::string last_error;  // Embree's message, set by its error callback on the building thread

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }

  // Throws if Embree reported an error since the last check.
  void check(const char* what) {
    const RTCError code = rtcGetDeviceError(device);
    if (code != RTC_ERROR_NONE)
      throw std::runtime_error(std::string("embree: ") + what + " failed: " + error_name(code) +
                               (last_error.empty() ? "" : " (" + last_error + ")"));
  }
};

EmbreeScene::EmbreeScene(const std::vector<glm::vec3>& positions, const std::vector<glm::uvec3>& triangles,
                         const std::vector<std::uint8_t>& cullable)
    : impl_(std::make_unique<Impl>()) {
  if (cullable.size() != triangles.size()) throw std::invalid_argument("embree scene: one cull flag per triangle");
  for (const glm::uvec3& t : triangles)
    if (t.x >= positions.size() || t.y >= positions.size() || t.z >= positions.size())
      throw std::invalid_argument("embree scene: triangle index out of range");
  if (triangles.empty()) return;  // Embree is not needed to miss everything

  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device)
    throw std::runtime_error(std::string("embree: rtcNewDevice failed: ") + error_name(rtcGetDeviceError(nullptr)));
  rtcSetDeviceErrorFunction(
      impl_->device, [](void* user, RTCError, const char* message) { static_cast<Impl*>(user)->last_error = message; },
      impl_.get());

  impl_->faces.reserve(triangles.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const glm::uvec3 t = triangles[i];
    const glm::vec3 n = glm::cross(positions[t.y] - positions[t.x], positions[t.z] - positions[t.x]);
    impl_->faces.emplace_back(n, cullable[i] ? 1.0f : 0.0f);
  }

  impl_->scene = rtcNewScene(impl_->device);
  impl_->check("rtcNewScene");
  // Robust: no shortcuts that trade accuracy for speed (watertight edges, a reference's job).
  // Context filter: the camera's back-face culling is chosen per ray.
  rtcSetSceneFlags(impl_->scene, RTCSceneFlags(RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION));
  // A scene is built once and traced by many renders (sweeps): spend the time on a better tree.
  rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);

  RTCGeometry geometry = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
  impl_->check("rtcNewGeometry");
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                               3 * sizeof(float), positions.size()));
  auto* indices = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), triangles.size()));
  if (!vertices || !indices) {
    rtcReleaseGeometry(geometry);
    impl_->check("rtcSetNewGeometryBuffer");
    throw std::runtime_error("embree: rtcSetNewGeometryBuffer returned no buffer");
  }
  std::memcpy(vertices, positions.data(), positions.size() * sizeof(glm::vec3));
  std::memcpy(indices, triangles.data(), triangles.size() * sizeof(glm::uvec3));
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(impl_->scene, geometry);
  rtcReleaseGeometry(geometry);  // the scene holds it now
  impl_->check("building the triangle geometry");
  rtcCommitScene(impl_->scene);
  impl_->check("rtcCommitScene");
}

EmbreeScene::~EmbreeScene() = default;

std::optional<EmbreeScene::Hit> EmbreeScene::closest(glm::vec3 origin, glm::vec3 direction, float t_far,
                                                     bool cull_back_faces) const {
  if (!impl_->scene) return std::nullopt;
  CullContext context;
  rtcInitIntersectContext(&context.base);
  if (cull_back_faces) context.base.filter = reject_back_faces;
  context.faces = impl_->faces.data();
  RTCRayHit rayhit{};
  rayhit.ray = make_ray(origin, direction, t_far);
  rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &context.base, &rayhit);
  if (rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  return Hit{rayhit.hit.primID, rayhit.hit.u, rayhit.hit.v, rayhit.ray.tfar};
}

bool EmbreeScene::occluded(glm::vec3 origin, glm::vec3 direction, float t_far) const {
  if (!impl_->scene) return false;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = make_ray(origin, direction, t_far);
  rtcOccluded1(impl_->scene, &context, &ray);
  return ray.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
}

}  // namespace reference
