// The hostile cases of the stability suite (docs/stability.md): each a scene and a request
// that push one thing to an extreme. The invariants are checked in test_stability.cpp.
#pragma once

#include "api/render_request.hpp"
#include "scene/scene.hpp"

#include <functional>
#include <string>
#include <vector>

namespace stability {

struct Case {
  std::string name;
  std::string what;  // the extreme, in a few words
  std::function<scene::Scene()> scene;
  api::RenderRequest request;  // at a small size; the scene comes from `scene`
};

const std::vector<Case>& cases();

// The Cornell box scaled by `s` (metres per unit), its lights' intensities by s^2 so that
// the image stays the same.
scene::Scene scaled_cornell(float s);

// A closed white box (albedo 1: every bounce keeps all the light) lit from inside.
scene::Scene white_closed_box();

}  // namespace stability
