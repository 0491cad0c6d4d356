// The three kinds of request error (api/request_error.hpp) answered by their type, not by the
// field they name: a scene that does not exist 404, a valid request the device or scene cannot
// serve 422, an invalid one 400.
#include "server/http_errors.hpp"

#include <gtest/gtest.h>

namespace server {
namespace {

TEST(ErrorKinds, EachKindHasItsStatusAndCodeWhateverItsField) {
  const HttpError missing = request_error(api::NotFound("base.scene", "unknown scene 'x'"));
  EXPECT_EQ(missing.status, 404);
  EXPECT_EQ(missing.code, "scene_not_found");
  EXPECT_EQ(missing.field, "base.scene");
  EXPECT_EQ(missing.message, "unknown scene 'x'");

  const HttpError too_big = request_error(api::DoesNotFit("scene", "needs more than the device has"));
  EXPECT_EQ(too_big.status, 422) << "the field does not decide: the type does";
  EXPECT_EQ(too_big.code, "does_not_fit");

  const HttpError invalid = request_error(api::RequestError("lpv.grid", "must be at least 2"));
  EXPECT_EQ(invalid.status, 400);
  EXPECT_EQ(invalid.code, "invalid_value");
  EXPECT_EQ(invalid.field, "lpv.grid");
}

}  // namespace
}  // namespace server
