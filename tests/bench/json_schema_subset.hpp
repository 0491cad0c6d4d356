// A JSON Schema validator for the keywords our schemas use (bench/results.schema.json), so
// the tests check documents against the schema file itself without a new dependency:
// $ref ("#/$defs/NAME"), type, const, enum, properties, required, additionalProperties,
// items, oneOf, minimum, maximum, minLength, minItems, maxItems, pattern. Annotations ($schema, $id,
// $defs, title, description, default, examples, $comment) are ignored; any other keyword
// is reported as unsupported, so a check never passes by skipping a rule it cannot do.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace schema_test {

// The problems, each "PATH: what is wrong" (PATH "$" is the document); empty when valid.
std::vector<std::string> validate(const nlohmann::json& schema, const nlohmann::json& document);

}  // namespace schema_test
