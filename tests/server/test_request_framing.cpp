// server/request_framing: where a request's body ends, read from its head, and the heads
// whose framing two readers could read apart (RFC 9112, sections 2.2, 5 and 6), refused.
#include "server/request_framing.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

using server::BodyFraming;
using server::FramedHead;
using server::HttpError;

constexpr std::uint64_t kMax = 1000;

std::string head(const std::string& fields, const std::string& version = "HTTP/1.1") {
  return "POST /v1/render " + version + "\r\nHost: 127.0.0.1\r\n" + fields + "\r\n";
}

FramedHead framed(const std::string& text) {
  const auto result = server::frame_request(text, kMax);
  if (const HttpError* e = std::get_if<HttpError>(&result)) ADD_FAILURE() << "refused: " << e->message;
  return std::holds_alternative<FramedHead>(result) ? std::get<FramedHead>(result) : FramedHead{};
}

int refusal(const std::string& text) {
  const auto result = server::frame_request(text, kMax);
  return std::holds_alternative<HttpError>(result) ? std::get<HttpError>(result).status : 0;
}

TEST(RequestFraming, TheBodyEndsWhereTheHeadSays) {
  EXPECT_EQ(framed(head("")).body.kind, BodyFraming::Kind::none);
  EXPECT_EQ(framed(head("Content-Length: 0\r\n")).body.kind, BodyFraming::Kind::none);
  const FramedHead sized = framed(head("content-length:  42 \r\n"));
  EXPECT_EQ(sized.body.kind, BodyFraming::Kind::length);
  EXPECT_EQ(sized.body.length, 42u);
  EXPECT_EQ(framed(head("Content-Length: 7\r\nContent-Length: 7, 7\r\n")).body.length, 7u) << "the same value repeated";
  EXPECT_EQ(framed(head("Content-Length: 0007\r\n")).body.length, 7u);
  EXPECT_EQ(framed(head("Transfer-Encoding: Chunked\r\n")).body.kind, BodyFraming::Kind::chunked);
  EXPECT_EQ(framed(head("Content-Length: 1000\r\n")).body.length, kMax) << "the cap itself is taken";
}

TEST(RequestFraming, AmbiguousFramingIsRefused) {
  EXPECT_EQ(refusal(head("Content-Length: 5\r\nTransfer-Encoding: chunked\r\n")), 400);
  EXPECT_EQ(refusal(head("Content-Length: 5\r\nContent-Length: 6\r\n")), 400);
  EXPECT_EQ(refusal(head("Content-Length: 5, 6\r\n")), 400);
  EXPECT_EQ(refusal(head("Transfer-Encoding: chunked, identity\r\n")), 400) << "chunked not last";
  EXPECT_EQ(refusal(head("Transfer-Encoding: chunked\r\nTransfer-Encoding: identity\r\n")), 400);
  EXPECT_EQ(refusal(head("Transfer-Encoding: gzip, chunked\r\n")), 501) << "a coding not read here";
  EXPECT_EQ(refusal(head("Transfer-Encoding:\r\n")), 400);
  EXPECT_EQ(refusal(head("Transfer-Encoding: chunked\r\n", "HTTP/1.0")), 400);
  EXPECT_EQ(refusal(head("Transfer-Encoding:\r\n chunked\r\n")), 400) << "obs-fold";
  EXPECT_EQ(refusal(head("X-A: 1\r\n\tfolded\r\n")), 400) << "obs-fold with a tab";
  EXPECT_EQ(refusal(head("Transfer-Encoding : chunked\r\n")), 400) << "a space before the colon";
  EXPECT_EQ(refusal(head("No colon here\r\n")), 400);
  EXPECT_EQ(refusal(head("Content-Length: 99999999999999999999999\r\n")), 400) << "too large to parse";
  for (const char* bad : {"+5", "-5", "5 5", "0x10", "", "5;"})
    EXPECT_EQ(refusal(head("Content-Length: " + std::string(bad) + "\r\n")), 400) << bad;
  EXPECT_EQ(refusal(head("Content-Length: 1001\r\n")), 413);
  EXPECT_EQ(refusal(head("Content-Length: 99999999999\r\n")), 413);
}

TEST(RequestFraming, LinesEndWithCrlfOnly) {
  EXPECT_EQ(refusal("POST / HTTP/1.1\nHost: x\n\n"), 400);
  EXPECT_EQ(refusal(head("X-A: 1\nContent-Length: 5\r\n")), 400) << "one bare LF hides a field from one reader";
  EXPECT_EQ(refusal(head("X-A: 1\rContent-Length: 5\r\n")), 400) << "a bare CR";
  EXPECT_EQ(refusal(head(std::string("X-A: a\0b\r\n", 10))), 400) << "a NUL";
  EXPECT_EQ(server::find_bare_line_break("a\r\nb\r", 0), std::string::npos) << "a CR at the end waits for its LF";
  EXPECT_EQ(server::find_bare_line_break("a\r\nb\rc", 0), 4u);
  EXPECT_EQ(server::find_bare_line_break("a\r\nb\nc", 3), 4u);
}

TEST(RequestFraming, EmptyFieldsAreNamed) {
  const FramedHead h = framed(head("X-Deadline-Ms:\r\nX-Other: 1\r\nX-Blank:   \r\n"));
  EXPECT_EQ(h.empty_fields, (std::vector<std::string>{"X-Deadline-Ms", "X-Blank"}));
}

}  // namespace
