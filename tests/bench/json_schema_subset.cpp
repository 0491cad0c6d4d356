#include "json_schema_subset.hpp"

#include <algorithm>
#include <cmath>
#include <regex>
#include <set>
#include <stdexcept>

namespace schema_test {
namespace {

using nlohmann::json;

const std::set<std::string> kAnnotations = {"$schema", "$id", "$defs", "title", "description", "default", "examples",
                                            "$comment"};

bool has_type(const json& value, const std::string& type) {
  if (type == "object") return value.is_object();
  if (type == "array") return value.is_array();
  if (type == "string") return value.is_string();
  if (type == "boolean") return value.is_boolean();
  if (type == "null") return value.is_null();
  if (type == "number") return value.is_number();
  if (type == "integer")
    return value.is_number_integer() || (value.is_number_float() && std::trunc(value.get<double>()) == value.get<double>());
  throw std::runtime_error("unknown type " + type);
}

class Validator {
 public:
  explicit Validator(const json& root) : root_(root) {}

  void check(const json& schema, const json& value, const std::string& path) {
    for (const auto& [keyword, rule] : schema.items()) {
      if (kAnnotations.count(keyword)) continue;
      if (keyword == "$ref") {
        check(resolve(rule.get<std::string>()), value, path);
      } else if (keyword == "type") {
        const json types = rule.is_array() ? rule : json::array({rule});
        bool any = false;
        for (const auto& t : types) any = any || has_type(value, t.get<std::string>());
        if (!any) fail(path, "is not of type " + rule.dump());
      } else if (keyword == "const") {
        if (value != rule) fail(path, "must be " + rule.dump());
      } else if (keyword == "enum") {
        if (std::find(rule.begin(), rule.end(), value) == rule.end()) fail(path, "must be one of " + rule.dump());
      } else if (keyword == "required") {
        for (const auto& key : rule)
          if (value.is_object() && !value.contains(key.get<std::string>()))
            fail(path, "lacks the required key " + key.dump());
      } else if (keyword == "properties") {
        if (!value.is_object()) continue;
        for (const auto& [key, sub] : rule.items())
          if (value.contains(key)) check(sub, value[key], path + "." + key);
      } else if (keyword == "additionalProperties") {
        if (!value.is_object()) continue;
        const json& known = schema.contains("properties") ? schema["properties"] : json::object();
        for (const auto& [key, sub] : value.items()) {
          if (known.contains(key)) continue;
          if (rule.is_boolean() && !rule.get<bool>()) fail(path, "has the key \"" + key + "\" the schema does not allow");
          if (rule.is_object()) check(rule, sub, path + "." + key);
        }
      } else if (keyword == "items") {
        if (!value.is_array()) continue;
        for (std::size_t i = 0; i < value.size(); ++i) check(rule, value[i], path + "[" + std::to_string(i) + "]");
      } else if (keyword == "oneOf") {
        std::size_t matches = 0;
        for (const auto& alternative : rule) {
          Validator trial(root_);
          trial.check(alternative, value, path);
          matches += trial.problems.empty() ? 1 : 0;
        }
        if (matches != 1) fail(path, "matches " + std::to_string(matches) + " of the oneOf alternatives, not 1");
      } else if (keyword == "minimum") {
        if (value.is_number() && value.get<double>() < rule.get<double>()) fail(path, "is below " + rule.dump());
      } else if (keyword == "maximum") {
        if (value.is_number() && value.get<double>() > rule.get<double>()) fail(path, "is above " + rule.dump());
      } else if (keyword == "minLength") {
        if (value.is_string() && value.get_ref<const std::string&>().size() < rule.get<std::size_t>())
          fail(path, "is shorter than " + rule.dump());
      } else if (keyword == "minItems") {
        if (value.is_array() && value.size() < rule.get<std::size_t>()) fail(path, "has fewer items than " + rule.dump());
      } else if (keyword == "maxItems") {
        if (value.is_array() && value.size() > rule.get<std::size_t>()) fail(path, "has more items than " + rule.dump());
      } else if (keyword == "pattern") {
        if (value.is_string() && !std::regex_search(value.get_ref<const std::string&>(), std::regex(rule.get<std::string>())))
          fail(path, "does not match " + rule.dump());
      } else {
        fail(path, "the schema uses \"" + keyword + "\", which this validator does not support");
      }
    }
  }

  std::vector<std::string> problems;

 private:
  const json& resolve(const std::string& ref) const {
    const std::string prefix = "#/$defs/";
    if (ref.rfind(prefix, 0) != 0 || !root_["$defs"].contains(ref.substr(prefix.size())))
      throw std::runtime_error("unsupported or dangling $ref " + ref);
    return root_["$defs"][ref.substr(prefix.size())];
  }
  void fail(const std::string& path, const std::string& what) { problems.push_back(path + ": " + what); }

  const json& root_;
};

}  // namespace

std::vector<std::string> validate(const nlohmann::json& schema, const nlohmann::json& document) {
  Validator validator(schema);
  validator.check(schema, document, "$");
  return validator.problems;
}

}  // namespace schema_test
