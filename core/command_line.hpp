// One walk over a command line for every program's options (lpv-render, lpv-bench, lpv-server):
// "-h" or "--help", options by name or alias, "--name value" or "--name=value", and the
// words that are no option, with the same rules and errors everywhere. What an option means
// is its program's: the walk takes the program's own table, whose entries have a `name`, an
// `alias` ("" for none) and `takes_value` (OptionSpec is one such entry, with a setter), and
// the program applies the items in order.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace core {

template <class Options>
struct OptionSpec {
  std::string_view name;   // "--output"
  std::string_view alias;  // "-o", or "" for none
  bool takes_value = true;
  // `name` as written (the name or the alias); `value` is "" for a switch given without one.
  std::function<void(Options&, std::string_view name, std::string_view value)> set;
};

// A usage error of the command line itself, an unknown option or one without its value, when
// the program names no error type of its own.
class CommandLineError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

template <class Option>
struct CommandLineItem {
  enum class Kind { help, option, word } kind = Kind::word;
  const Option* option = nullptr;  // Kind::option: its entry in the program's table
  std::string name;                             // the option as written, without "=value"
  std::string value;                            // the option's value, or the word
};

// The items of argv[1..argc), in order. An option's value is the next argument, unless that
// is missing or is another option ("-o -q" forgot the file; "-" alone is a value: standard
// input or output); a switch takes a value only as "--name=value". Errors are thrown as
// `Error`, made from their message (the program's usage error).
template <class Error = CommandLineError, class Option>
std::vector<CommandLineItem<Option>> walk_command_line(int argc, const char* const* argv,
                                                      const std::vector<Option>& options) {
  using Item = CommandLineItem<Option>;
  std::vector<Item> items;
  for (int i = 1; i < argc; ++i) {
    std::string_view arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      items.push_back({Item::Kind::help, nullptr, std::string(arg), ""});
      continue;
    }
    if (arg.size() < 2 || arg[0] != '-') {
      items.push_back({Item::Kind::word, nullptr, "", std::string(arg)});
      continue;
    }
    const auto equals = arg.starts_with("--") ? arg.find('=') : std::string_view::npos;
    const std::string_view name = arg.substr(0, equals);
    const Option* spec = nullptr;
    for (const Option& o : options)
      if (name == o.name || (!o.alias.empty() && name == o.alias)) spec = &o;
    if (!spec) throw Error("unknown option " + std::string(name));
    std::string value;
    if (equals != std::string_view::npos) {
      value = arg.substr(equals + 1);
    } else if (spec->takes_value) {
      const bool missing = i + 1 >= argc || (argv[i + 1][0] == '-' && argv[i + 1][1] != '\0');
      if (missing) throw Error("option " + std::string(name) + " needs a value");
      value = argv[++i];
    }
    items.push_back({Item::Kind::option, spec, std::string(name), std::move(value)});
  }
  return items;
}

}  // namespace core
