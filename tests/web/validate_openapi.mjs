// The contract (api/openapi.yaml) checked by an independent OpenAPI 3.0 validator,
// @apidevtools/swagger-parser (from package-lock.json here, installed by
// scripts/install-deps.sh): the server's own tests read the file with its own YAML
// parser, which accepts mistakes such as an unquoted comma in a flow mapping that splits a
// description into a stray key; client generators and documentation tools do not.
// Run by CTest as `openapi_valid`:   node validate_openapi.mjs OPENAPI.yaml
let SwaggerParser;
try {
  ({ default: SwaggerParser } = await import('@apidevtools/swagger-parser'));
} catch (error) {
  console.error(`openapi_valid: @apidevtools/swagger-parser is not installed (${error.message}); ` +
                'scripts/install-deps.sh runs npm ci in tests/web');
  process.exit(1);
}

const file = process.argv[2];
if (!file) {
  console.error('usage: node validate_openapi.mjs OPENAPI.yaml');
  process.exit(2);
}
try {
  const api = await SwaggerParser.validate(file);
  console.log(`${file}: valid OpenAPI ${api.openapi} (${Object.keys(api.paths).length} paths)`);
} catch (error) {
  // The errors themselves, without the echo of each: every schema around a bad one fails
  // too, as neither alternative of "a schema or a $ref" (oneOf, required $ref).
  const echo = (d) => d.keyword === 'oneOf' || (d.keyword === 'required' && d.params?.missingProperty === '$ref');
  const problems = (error.details ?? []).filter((d) => !echo(d));
  console.error(`${file}: not valid OpenAPI: ${error.message.split('\n')[0]}`);
  for (const d of problems) console.error(`  ${d.instancePath}: ${d.message} ${JSON.stringify(d.params)}`);
  if (!problems.length) console.error(error.message);
  process.exit(1);
}
