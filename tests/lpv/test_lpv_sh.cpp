// The LPV maths of shaders/shared/lpv_sh.h checked against integrals over the sphere and
// the cell faces, computed here by quadrature: basis, cosine lobe, emitter normalisation,
// face solid angles, and flux conservation of one propagation step.
#include "shaders/shared/lpv_sh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

namespace {

constexpr double kPi = 3.14159265358979323846;

// Integral of f over the unit sphere: midpoint rule in (z, phi), which is area-uniform.
double integrate_sphere(const std::function<double(glm::vec3)>& f, int n = 1200) {
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double z = -1.0 + (i + 0.5) * 2.0 / n;
    const double r = std::sqrt(1.0 - z * z);
    for (int j = 0; j < 2 * n; ++j) {
      const double phi = (j + 0.5) * kPi / n;
      sum += f(glm::vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)));
    }
  }
  return sum * (2.0 / n) * (kPi / n);
}

// Solid angle of the axis-aligned rectangle {x = plane} x [y0, y1] x [z0, z1] seen from the origin.
double rectangle_solid_angle(double plane, double y0, double y1, double z0, double z1, int n = 2000) {
  double sum = 0.0;
  const double dy = (y1 - y0) / n, dz = (z1 - z0) / n;
  for (int i = 0; i < n; ++i) {
    const double y = y0 + (i + 0.5) * dy;
    for (int j = 0; j < n; ++j) {
      const double z = z0 + (j + 0.5) * dz;
      sum += plane / std::pow(plane * plane + y * y + z * z, 1.5);
    }
  }
  return sum * dy * dz;
}

// In cell units from the source cell's centre: the neighbour along +x spans x in [0.5, 1.5].
const double kFarFace = rectangle_solid_angle(1.5, -0.5, 0.5, -0.5, 0.5);
// A side face of the neighbour along +y: the plane x = 0.5 with y in [0.5, 1.5].
const double kSideFace = rectangle_solid_angle(0.5, 0.5, 1.5, -0.5, 0.5);

TEST(FaceSolidAngles, MatchTheirIntegralsAndClosedForms) {
  EXPECT_NEAR(gpu::LPV_FAR_FACE_SOLID_ANGLE, kFarFace, 1e-7);
  EXPECT_NEAR(gpu::LPV_SIDE_FACE_SOLID_ANGLE, kSideFace, 1e-7);
  EXPECT_NEAR(4.0 * std::asin(0.1), kFarFace, 1e-7);
  EXPECT_NEAR(4.0 * std::atan(std::sqrt(11.0) / 33.0), kFarFace, 1e-7);
  EXPECT_NEAR(2.0 * std::atan(3.0 / std::sqrt(11.0)) - kPi / 3.0, kSideFace, 1e-7);
}

TEST(FaceSolidAngles, SixNeighboursCoverTheSphere) {
  EXPECT_NEAR(gpu::LPV_FAR_FACE_SOLID_ANGLE + 4.0 * gpu::LPV_SIDE_FACE_SOLID_ANGLE, 2.0 * kPi / 3.0, 1e-7);
  // The widely copied side constant with two digits swapped is measurably wrong.
  EXPECT_GT(std::abs(0.4234413544 - kSideFace), 5e-6);
}

TEST(ShBasis, IsOrthonormal) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double integral =
          integrate_sphere([&](glm::vec3 w) { return double(gpu::sh_basis(w)[i]) * gpu::sh_basis(w)[j]; });
      EXPECT_NEAR(integral, i == j ? 1.0 : 0.0, 1e-5) << i << "," << j;
    }
}

TEST(ShCosineLobe, IsTheProjectionOfTheClampedCosine) {
  std::mt19937 rng(7);
  std::normal_distribution<float> gauss;
  for (int k = 0; k < 4; ++k) {
    const glm::vec3 n = glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng)));
    const glm::vec4 lobe = gpu::sh_cosine_lobe(n);
    for (int i = 0; i < 4; ++i) {
      const double projection = integrate_sphere(
          [&](glm::vec3 w) { return std::max(0.0, double(glm::dot(n, w))) * gpu::sh_basis(w)[i]; });
      EXPECT_NEAR(lobe[i], projection, 2e-5) << "normal " << k << " coefficient " << i;
    }
  }
}

TEST(ShDiffuseEmitter, CarriesExactlyItsFlux) {
  const glm::vec3 n = glm::normalize(glm::vec3(0.3f, -0.8f, 0.5f));
  const float phi = 7.5f;
  // The exact distribution phi / pi * max(0, <n, w>) integrates to phi ...
  EXPECT_NEAR(integrate_sphere([&](glm::vec3 w) { return phi / kPi * std::max(0.0f, glm::dot(n, w)); }), phi, 1e-4);
  // ... and so does its SH projection, through the DC term alone.
  EXPECT_NEAR(gpu::sh_flux(gpu::sh_diffuse_emitter(n, phi)), phi, 1e-5);
  const glm::vec4 sh = gpu::sh_diffuse_emitter(n, phi);
  EXPECT_NEAR(integrate_sphere([&](glm::vec3 w) { return gpu::sh_evaluate(sh, w); }), phi, 1e-4);
}

TEST(ShEvaluate, ReproducesTheCosineLobeInItsDirection) {
  const glm::vec3 n(0.0f, 0.0f, 1.0f);
  // Two bands approximate max(0, cos): 1/4 + cos/2, so 3/4 at the pole and 1/4 on the equator.
  EXPECT_NEAR(gpu::sh_evaluate(gpu::sh_cosine_lobe(n), n), 0.75f, 1e-6f);
  EXPECT_NEAR(gpu::sh_evaluate(gpu::sh_cosine_lobe(n), glm::vec3(1, 0, 0)), 0.25f, 1e-6f);
}

// The six axis directions and, for each, its four side axes.
std::vector<std::pair<glm::vec3, std::vector<glm::vec3>>> neighbours() {
  const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  std::vector<std::pair<glm::vec3, std::vector<glm::vec3>>> result;
  for (int a = 0; a < 3; ++a)
    for (float s : {1.0f, -1.0f}) {
      std::vector<glm::vec3> sides;
      for (int b = 0; b < 3; ++b)
        if (b != a)
          for (float t : {1.0f, -1.0f}) sides.push_back(t * axes[b]);
      result.push_back({s * axes[a], sides});
    }
  return result;
}

TEST(Propagation, FaceDirectionsPointAtTheFaceCentres) {
  const glm::vec3 far = gpu::lpv_face_direction(glm::vec3(1, 0, 0), glm::vec3(0));
  EXPECT_EQ(far, glm::vec3(1, 0, 0));
  // Annotations 6.1: a side face centre is (1, 1/2) cells away, direction (2, 1) / sqrt(5).
  const glm::vec3 side = gpu::lpv_face_direction(glm::vec3(1, 0, 0), glm::vec3(0, 1, 0));
  EXPECT_NEAR(side.x, 2.0 / std::sqrt(5.0), 1e-6);
  EXPECT_NEAR(side.y, 1.0 / std::sqrt(5.0), 1e-6);
}

// One gather step, unoccluded: the flux through each of the 30 faces, solid angle times the
// intensity towards the face centre, re-emitted in the neighbour as a diffuse emitter along
// the face normal. An isotropic source loses nothing.
TEST(Propagation, IsotropicSourceConservesFluxThroughAllThirtyFaces) {
  const glm::vec4 source(1.3f, 0.0f, 0.0f, 0.0f);  // isotropic: DC only
  double through_faces = 0.0, reprojected = 0.0;
  for (const auto& [ahead, sides] : neighbours()) {
    const float far_flux = gpu::LPV_FAR_FACE_SOLID_ANGLE * gpu::sh_evaluate(source, ahead);
    through_faces += far_flux;
    reprojected += gpu::sh_flux(gpu::sh_diffuse_emitter(ahead, far_flux));
    for (const glm::vec3& side : sides) {
      const float side_flux =
          gpu::LPV_SIDE_FACE_SOLID_ANGLE * gpu::sh_evaluate(source, gpu::lpv_face_direction(ahead, side));
      through_faces += side_flux;
      reprojected += gpu::sh_flux(gpu::sh_diffuse_emitter(side, side_flux));
    }
  }
  EXPECT_NEAR(through_faces, gpu::sh_flux(source), 1e-5 * gpu::sh_flux(source));
  EXPECT_NEAR(reprojected, through_faces, 1e-5 * through_faces);
}

// The sender form propagation reads: A + sqrt(5) <P, w> is the SH's value in every direction
// w, and on the faces of the neighbour along sigma * a it is A + sqrt(5) sigma P_a (far face)
// and A + 2 sigma P_a +- P_b (side faces), the shared-term form lpv_propagate.comp computes.
TEST(SenderForm, EvaluatesTheShAndGivesTheFaceValues) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  const float sqrt5 = std::sqrt(5.0f);
  for (int trial = 0; trial < 100; ++trial) {
    const glm::vec4 sh(u(rng), u(rng), u(rng), u(rng));
    const glm::vec4 e = gpu::lpv_sender_form(sh);
    const glm::vec3 p(e.y, e.z, e.w);
    const glm::vec3 w = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)));
    EXPECT_NEAR(e.x + sqrt5 * glm::dot(p, w), gpu::sh_evaluate(sh, w), 1e-6f);
    for (const auto& [ahead, sides] : neighbours()) {
      const float sigma_pa = glm::dot(p, ahead);  // ahead = sigma * a
      EXPECT_NEAR(e.x + sqrt5 * sigma_pa, gpu::sh_evaluate(sh, ahead), 1e-6f);
      for (const glm::vec3& side : sides)
        EXPECT_NEAR(e.x + 2.0f * sigma_pa + glm::dot(p, side),
                    gpu::sh_evaluate(sh, gpu::lpv_face_direction(ahead, side)), 1e-6f);
    }
  }
}


// Blocking: a face's blocking SH is its blockers' potentials times their cosine lobes
// (lpv_geometry_inject.comp). Projected, one plane of potential p stops p |<n, w>| of the
// light along w from either side: nothing that grazes it, all of p head-on. The paper's
// one-sided lobe stops p (1/4 + 1/2 <n, -w>): a quarter grazing, 3/4 head-on, none from behind.
TEST(Blocking, ProjectedStopsTheBlockersProjectedAreaFromEitherSide) {
  const glm::vec3 n = glm::normalize(glm::vec3(0.3f, 1.0f, -0.2f));
  const float p = 0.8f;
  const glm::vec4 b = gpu::sh_cosine_lobe(n) * p;
  std::mt19937 rng(5);
  std::normal_distribution<float> g(0.0f, 1.0f);
  for (int i = 0; i < 200; ++i) {
    const glm::vec3 w = glm::normalize(glm::vec3(g(rng), g(rng), g(rng)));
    EXPECT_NEAR(gpu::lpv_transmitted(b, w, 0.0f, 1.0f), 1.0f - p * std::abs(glm::dot(n, w)), 1e-5f);
    const float one_sided = p * (0.25f + 0.5f * glm::dot(n, -w));
    EXPECT_NEAR(gpu::lpv_transmitted(b, w, 0.0f, 0.0f), 1.0f - std::clamp(one_sided, 0.0f, 1.0f), 1e-5f);
  }
  const glm::vec3 grazing = glm::normalize(glm::cross(n, glm::vec3(1, 0, 0)));
  EXPECT_NEAR(gpu::lpv_transmitted(b, grazing, 0.0f, 1.0f), 1.0f, 1e-6f);
  EXPECT_NEAR(gpu::lpv_transmitted(b, grazing, 0.0f, 0.0f), 1.0f - p / 4.0f, 1e-6f);
  EXPECT_NEAR(gpu::lpv_transmitted(b, -n, 0.0f, 1.0f), 1.0f - p, 1e-6f);
  EXPECT_NEAR(gpu::lpv_transmitted(b, n, 0.0f, 1.0f), 1.0f - p, 1e-6f) << "from behind, as an opaque surface";
  EXPECT_NEAR(gpu::lpv_transmitted(b, -n, 0.0f, 0.0f), 1.0f - 0.75f * p, 1e-6f);
  EXPECT_NEAR(gpu::lpv_transmitted(b, n, 0.0f, 0.0f), 1.0f, 1e-6f);
  // More than a face's worth of one plane stops everything.
  EXPECT_EQ(gpu::lpv_transmitted(gpu::sh_cosine_lobe(glm::vec3(1, 0, 0)) * 3.0f, glm::vec3(1, 0, 0), 0.0f, 1.0f), 0.0f);
}

// A plane's blocking with the closed part (lpv_closed_blocking) taken into account: for one
// open plane the first moment still decides in every direction a far face passes (along an
// axis), whatever the plane's slant, and in every direction for a plane along an axis. The
// two sides of a thin wall, whose first moments cancel, stop what one plane does.
TEST(Blocking, TheClosedPartLeavesOnePlaneAloneAndStopsLightAtAThinWall) {
  const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const float p = 0.7f;
  auto transmitted = [](const glm::vec4& sh, const glm::vec3& spread, const glm::vec3& w) {
    return gpu::lpv_transmitted(sh, w, gpu::lpv_closed_blocking(spread, w), 1.0f);
  };
  std::mt19937 rng(9);
  std::normal_distribution<float> g(0.0f, 1.0f);
  for (int i = 0; i < 200; ++i) {
    const glm::vec3 n = glm::normalize(glm::vec3(g(rng), g(rng), g(rng)));
    const glm::vec3 w = glm::normalize(glm::vec3(g(rng), g(rng), g(rng)));
    for (const glm::vec3& a : axes) {
      // A slanted plane, light along an axis.
      EXPECT_NEAR(transmitted(gpu::sh_cosine_lobe(n) * p, glm::abs(n) * p, a), 1.0f - p * std::abs(glm::dot(n, a)),
                  1e-5f);
      // A plane along an axis, light any way: one open plane, then both sides of a thin wall.
      const float head_on = 1.0f - p * std::abs(glm::dot(a, w));
      EXPECT_NEAR(transmitted(gpu::sh_cosine_lobe(a) * p, a * p, w), head_on, 1e-5f);
      const glm::vec4 wall = (gpu::sh_cosine_lobe(a) + gpu::sh_cosine_lobe(-a)) * p;
      EXPECT_NEAR(gpu::lpv_transmitted(wall, w, 0.0f, 1.0f), 1.0f, 1e-5f) << "the first moments cancel";
      EXPECT_NEAR(transmitted(wall, 2.0f * a * p, w), head_on, 1e-5f);
    }
    // In general the closed part is at least half the blockers' summed projected area.
    const glm::vec3 m = glm::normalize(glm::vec3(g(rng), g(rng), g(rng)));
    const float sum = std::abs(glm::dot(n, w)) + std::abs(glm::dot(m, w));
    EXPECT_GE(gpu::lpv_closed_blocking(glm::abs(n) + glm::abs(m), w), 0.5f * sum - 1e-6f);
  }
}

// Shading reads each cell's SH made nowhere negative: its irradiance onto any surface is >= 0,
// an SH already so is unchanged, and the constant term (the flux) is kept.
TEST(ShNonnegativeIrradiance, NoDirectionGetsNegativeLightAndTheFluxIsKept) {
  std::mt19937 rng(9);
  std::normal_distribution<float> g(0.0f, 1.0f);
  int changed = 0;
  for (int i = 0; i < 500; ++i) {
    const glm::vec4 s(std::abs(g(rng)), g(rng), g(rng), g(rng));
    const glm::vec4 kept = gpu::sh_nonnegative_irradiance(s);
    EXPECT_EQ(kept.x, s.x);
    // Random directions, and the one the band-1 vector points away from, where it is least.
    float least = 1e30f, least_before = 1e30f;
    for (int j = 0; j <= 200; ++j) {
      const glm::vec3 n = j < 200 ? glm::normalize(glm::vec3(g(rng), g(rng), g(rng)))
                                  : glm::normalize(glm::vec3(s.w, s.y, -s.z));
      least = std::min(least, glm::dot(kept, gpu::sh_cosine_lobe(n)));
      least_before = std::min(least_before, glm::dot(s, gpu::sh_cosine_lobe(n)));
    }
    EXPECT_GE(least, -1e-5f * s.x);
    if (least_before >= 0.0f) {
      EXPECT_EQ(kept, s);
    }
    changed += kept != s;
  }
  EXPECT_GT(changed, 100) << "many of the random SH need it";
  // A hemisphere above a lit plane, I = A (1 + 3/2 <up, w>), is the limit: it lights the plane
  // with exactly zero, and stays as it is.
  const glm::vec4 hemisphere(1.0f / gpu::SH_C0, -1.5f / gpu::SH_C1, 0.0f, 0.0f);
  EXPECT_NEAR(glm::dot(gpu::sh_nonnegative_irradiance(hemisphere), gpu::sh_cosine_lobe(glm::vec3(0, -1, 0))), 0.0f,
              1e-5f);
  const glm::vec4 beam = hemisphere * glm::vec4(1, 2, 2, 2);
  EXPECT_NEAR(glm::length(gpu::sh_nonnegative_irradiance(beam) - hemisphere), 0.0f, 1e-5f);
  EXPECT_EQ(gpu::sh_nonnegative_irradiance(glm::vec4(-1, 1, 0, 0)), glm::vec4(0.0f));
}

}  // namespace
