#include "server/access.hpp"
#include "core/base64.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace server {
namespace {

TEST(Access, ConstantTimeEqualityIsEquality) {
  EXPECT_TRUE(equal_in_constant_time("", ""));
  EXPECT_TRUE(equal_in_constant_time("token", "token"));
  EXPECT_FALSE(equal_in_constant_time("token", "tokem"));
  EXPECT_FALSE(equal_in_constant_time("token", "token2"));
  EXPECT_FALSE(equal_in_constant_time("token", ""));
  EXPECT_FALSE(equal_in_constant_time(std::string_view("a\0b", 3), std::string_view("a\0c", 3)));
}

TEST(Access, BearerTokenNeedsTheSchemeAndTheExactToken) {
  EXPECT_TRUE(bearer_token_matches("Bearer abc", "abc"));
  EXPECT_TRUE(bearer_token_matches("bearer abc", "abc"));
  EXPECT_FALSE(bearer_token_matches("Bearer abcd", "abc"));
  EXPECT_FALSE(bearer_token_matches("Basic abc", "abc"));
  EXPECT_FALSE(bearer_token_matches("abc", "abc"));
  EXPECT_FALSE(bearer_token_matches("", "abc"));
  EXPECT_FALSE(bearer_token_matches("Bearer ", "abc"));
}

TEST(Access, AuthorityHostDropsThePortAndBracketsAndLowercases) {
  EXPECT_EQ(authority_host("127.0.0.1:8080"), "127.0.0.1");
  EXPECT_EQ(authority_host("LocalHost"), "localhost");
  EXPECT_EQ(authority_host("[::1]:8080"), "::1");
  EXPECT_EQ(authority_host("[::1]"), "::1");
  EXPECT_EQ(authority_host("Render.Example.COM:443"), "render.example.com");
  EXPECT_EQ(authority_host("::1"), "") << "a bare IPv6 address is no authority";
  EXPECT_EQ(authority_host("[::1"), "");
  EXPECT_EQ(authority_host("[::1]x"), "");
}

TEST(Access, OriginAuthorityIsTheHostAndPortOfTheOrigin) {
  EXPECT_EQ(origin_authority("http://127.0.0.1:8080"), "127.0.0.1:8080");
  EXPECT_EQ(origin_authority("https://Evil.Example"), "evil.example");
  EXPECT_EQ(origin_authority("null"), "");
  EXPECT_EQ(origin_authority("http://a.example/path"), "");
  EXPECT_EQ(origin_authority("http://user@a.example"), "");
  EXPECT_EQ(origin_authority("://a.example"), "");
}

TEST(Access, HostPolicyAllowsLoopbackAndTheNamedHostsOnly) {
  const HostPolicy loopback_only({});
  EXPECT_TRUE(loopback_only.allows("127.0.0.1:8080"));
  EXPECT_TRUE(loopback_only.allows("localhost:8080"));
  EXPECT_TRUE(loopback_only.allows("[::1]:8080"));
  EXPECT_FALSE(loopback_only.allows("evil.example:8080")) << "a DNS-rebinding page's name";
  EXPECT_FALSE(loopback_only.allows("192.168.1.2"));
  EXPECT_FALSE(loopback_only.allows(""));
  const HostPolicy named({"Render.Example.com", "10.0.0.5"});
  EXPECT_TRUE(named.allows("render.example.com:8080"));
  EXPECT_TRUE(named.allows("10.0.0.5"));
  EXPECT_FALSE(named.allows("other.example.com"));
  EXPECT_TRUE(HostPolicy({"*"}).allows("anything.example"));
}

TEST(Access, LoopbackHosts) {
  EXPECT_TRUE(is_loopback_host("127.0.0.1"));
  EXPECT_TRUE(is_loopback_host("127.8.9.10"));
  EXPECT_TRUE(is_loopback_host("::1"));
  EXPECT_TRUE(is_loopback_host("localhost"));
  EXPECT_FALSE(is_loopback_host("0.0.0.0"));
  EXPECT_FALSE(is_loopback_host("::"));
  EXPECT_FALSE(is_loopback_host("192.168.1.2"));
  EXPECT_FALSE(is_loopback_host("example.com"));
}

TEST(Base64, MatchesRfc4648TestVectors) {
  auto encode = [](std::string_view s) {
    return core::base64_encode(std::span(reinterpret_cast<const std::uint8_t*>(s.data()), s.size()));
  };
  EXPECT_EQ(encode(""), "");
  EXPECT_EQ(encode("f"), "Zg==");
  EXPECT_EQ(encode("fo"), "Zm8=");
  EXPECT_EQ(encode("foo"), "Zm9v");
  EXPECT_EQ(encode("foob"), "Zm9vYg==");
  EXPECT_EQ(encode("fooba"), "Zm9vYmE=");
  EXPECT_EQ(encode("foobar"), "Zm9vYmFy");
  const std::vector<std::uint8_t> high = {0xff, 0xfe, 0xfd};
  EXPECT_EQ(core::base64_encode(high), "//79");
}

TEST(Base64, DecodeInvertsEncodeAndRejectsWhatIsNotStrictBase64) {
  for (std::string_view s : {"", "f", "fo", "foo", "foob", "fooba", "foobar"}) {
    const std::vector<std::uint8_t> bytes(s.begin(), s.end());
    EXPECT_EQ(core::base64_decode(core::base64_encode(bytes)), bytes) << s;
  }
  EXPECT_EQ(core::base64_decode("//79"), (std::vector<std::uint8_t>{0xff, 0xfe, 0xfd}));
  for (std::string_view bad : {"Zg=", "Zg", "Z===", "Zm9v\n", "Zm*v", "=Zm9", "Zg==Zg=="})
    EXPECT_FALSE(core::base64_decode(bad).has_value()) << bad;
}

}  // namespace
}  // namespace server
