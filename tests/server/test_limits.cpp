#include "server/limits.hpp"

#include <gtest/gtest.h>

namespace server {
namespace {

std::string field_over_limit(const api::RenderRequest& request, const RenderLimits& limits) {
  try {
    check_limits(request, limits);
  } catch (const LimitExceeded& e) {
    return e.field();
  }
  return "";
}

TEST(Limits, TheDefaultRequestIsWithinTheDefaults) {
  EXPECT_EQ(field_over_limit(api::RenderRequest{}, RenderLimits{}), "");
}

TEST(Limits, EachLimitNamesItsField) {
  const RenderLimits limits{.max_pixels = 1000, .max_grid_cells = 8 * 8 * 8, .max_iterations = 4, .max_repeat = 2};
  api::RenderRequest r;
  r.output.width = 10;
  r.output.height = 10;
  r.lpv.grid = {8, 8, 8};
  r.lpv.iterations = 4;
  r.repeat = 2;
  EXPECT_EQ(field_over_limit(r, limits), "") << "exactly at every limit is allowed";

  api::RenderRequest pixels = r;
  pixels.output.width = 101;
  EXPECT_EQ(field_over_limit(pixels, limits), "output");
  api::RenderRequest cascades = r;
  cascades.lpv.cascades = 2;  // 2 x 8^3 cells
  EXPECT_EQ(field_over_limit(cascades, limits), "lpv.grid");
  api::RenderRequest grid = r;
  grid.lpv.grid = {8, 8, 9};
  EXPECT_EQ(field_over_limit(grid, limits), "lpv.grid");
  api::RenderRequest iterations = r;
  iterations.lpv.iterations = 5;
  EXPECT_EQ(field_over_limit(iterations, limits), "lpv.iterations");
  api::RenderRequest repeat = r;
  repeat.repeat = 3;
  EXPECT_EQ(field_over_limit(repeat, limits), "repeat");
}

TEST(Limits, LargeValuesDoNotOverflow) {
  api::RenderRequest r;
  r.output.width = 8192;
  r.output.height = 8192;
  EXPECT_EQ(field_over_limit(r, RenderLimits{}), "output");
}

}  // namespace
}  // namespace server
