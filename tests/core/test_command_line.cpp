// The one command-line walk of lpv-render, lpv-bench and lpv-server (core/command_line.hpp).
#include "core/command_line.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

struct Options {
  std::string output;
  bool quiet = false;
};

using Item = core::CommandLineItem<core::OptionSpec<Options>>;

const std::vector<core::OptionSpec<Options>> kOptions = {
    {"--output", "-o", true, [](Options& o, std::string_view, std::string_view v) { o.output = std::string(v); }},
    {"--quiet", "-q", false, [](Options& o, std::string_view, std::string_view) { o.quiet = true; }},
};

std::vector<Item> walk(std::vector<const char*> args) {
  args.insert(args.begin(), "program");
  return core::walk_command_line(int(args.size()), args.data(), kOptions);
}

std::string error_of(std::vector<const char*> args) {
  try {
    walk(std::move(args));
  } catch (const core::CommandLineError& e) {
    return e.what();
  }
  return "";
}

TEST(CommandLine, OptionsByNameOrAliasWithTheirValuesWordsAndHelpInOrder) {
  const auto items = walk({"request.json", "-o", "a.png", "--quiet", "--output=b.png", "-", "--help"});
  ASSERT_EQ(items.size(), 6u);
  EXPECT_EQ(items[0].kind, Item::Kind::word);
  EXPECT_EQ(items[0].value, "request.json");
  EXPECT_EQ(items[1].kind, Item::Kind::option);
  EXPECT_EQ(items[1].option, &kOptions[0]);
  EXPECT_EQ(items[1].name, "-o");
  EXPECT_EQ(items[1].value, "a.png");
  EXPECT_EQ(items[2].option, &kOptions[1]);
  EXPECT_EQ(items[2].value, "");
  EXPECT_EQ(items[3].name, "--output");
  EXPECT_EQ(items[3].value, "b.png");
  EXPECT_EQ(items[4].kind, Item::Kind::word) << "'-' alone is standard input or output";
  EXPECT_EQ(items[4].value, "-");
  EXPECT_EQ(items[5].kind, Item::Kind::help);
}

TEST(CommandLine, ASwitchTakesAValueOnlyAfterAnEqualsSign) {
  const auto items = walk({"--quiet", "file", "--quiet=0"});
  ASSERT_EQ(items.size(), 3u);
  EXPECT_EQ(items[1].kind, Item::Kind::word);
  EXPECT_EQ(items[2].value, "0");
}

TEST(CommandLine, ErrorsNameTheOption) {
  EXPECT_EQ(error_of({"--frobnicate"}), "unknown option --frobnicate");
  EXPECT_EQ(error_of({"--frobnicate=1"}), "unknown option --frobnicate");
  EXPECT_EQ(error_of({"-o"}), "option -o needs a value");
  EXPECT_EQ(error_of({"-o", "-q"}), "option -o needs a value") << "the next word is another option";
  EXPECT_EQ(error_of({"--output", "-1"}), "option --output needs a value");
  EXPECT_EQ(error_of({"-o=a.png"}), "unknown option -o=a.png") << "only long names take '='";
  EXPECT_EQ(error_of({"-o", "-"}), "");
}

}  // namespace
