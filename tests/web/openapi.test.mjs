// api/openapi.yaml against the OpenAPI 3.1 specification, and every answer the server tests
// got (logged by tests/server/server_fixture.cpp into PHOTON_API_RESPONSE_LOG, one JSON line
// per answer) against the document: its route and method are documented, its status is one
// of that operation's responses (or of those any request may get before routing,
// x-photon-before-routing), its content type one the response lists, and a JSON body
// validates against the response's schema. A field the server sends that the document does
// not describe, or describes otherwise, fails here.
//
//   PHOTON_API_RESPONSE_LOG=build/api-responses node --test tests/web/openapi.test.mjs

import assert from 'node:assert/strict';
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { Validator } from '@seriousme/openapi-schema-validator';
import Ajv2020 from 'ajv/dist/2020.js';
import { parse } from 'yaml';

const REPO = resolve(dirname(fileURLToPath(import.meta.url)), '..', '..');
const DOCUMENT = join(REPO, 'api', 'openapi.yaml');
const LOG = process.env.PHOTON_API_RESPONSE_LOG ? resolve(process.env.PHOTON_API_RESPONSE_LOG) : '';

const document = parse(readFileSync(DOCUMENT, 'utf8'));

test('api/openapi.yaml is a valid OpenAPI 3.1 document', async () => {
  const validator = new Validator();
  const result = await validator.validate(parse(readFileSync(DOCUMENT, 'utf8')));
  assert.ok(result.valid, `api/openapi.yaml: ${JSON.stringify(result.errors, null, 2)}`);
  assert.equal(validator.version, '3.1');
});

// "/api/v1/jobs/{id}/image" -> a pattern for concrete paths.
function templatePattern(template) {
  const escaped = template.replace(/[.*+?^$()|[\]\\]/g, '\\$&').replace(/\\?\{[^}]+\\?\}/g, '[^/]+');
  return new RegExp(`^${escaped}$`);
}

const routes = Object.keys(document.paths).map((template) => ({ template, pattern: templatePattern(template) }));

function operationFor(method, path) {
  // A literal segment beats a parameter ("/jobs/events" before "/jobs/{id}").
  const matches = routes.filter((r) => r.pattern.test(path));
  matches.sort((a, b) => (a.template.match(/\{/g) || []).length - (b.template.match(/\{/g) || []).length);
  for (const { template } of matches) {
    const operation = document.paths[template][method.toLowerCase()];
    if (operation) return { template, operation };
  }
  return null;
}

// A response object, with a $ref to components/responses followed.
function resolved(object) {
  if (!object || !object.$ref) return object;
  const parts = object.$ref.replace(/^#\//, '').split('/');
  return resolved(parts.reduce((node, key) => node[key.replace(/~1/g, '/').replace(/~0/g, '~')], document));
}

const DOCUMENT_ID = 'https://photon.invalid/openapi.json';
const validators = new Map();

function validatorFor(template, method, status, mediaType, schema) {
  const key = `${method} ${template} ${status} ${mediaType}`;
  if (!validators.has(key)) {
    validators.set(key, ajv.compile(rebase(schema)));
  }
  return validators.get(key);
}

// A schema taken out of the document: its local refs (#/components/...) point back into it.
function rebase(schema) {
  if (Array.isArray(schema)) return schema.map(rebase);
  if (!schema || typeof schema !== 'object') return schema;
  const out = {};
  for (const [k, v] of Object.entries(schema)) out[k] = k === '$ref' && v.startsWith('#/') ? DOCUMENT_ID + v : rebase(v);
  return out;
}

// Objects the document describes field by field have no fields it does not name: a field
// the server adds must be documented (unless the schema says otherwise).
function closed(node) {
  if (Array.isArray(node)) return node.forEach(closed);
  if (!node || typeof node !== 'object') return;
  if (node.properties && !('additionalProperties' in node) && !('unevaluatedProperties' in node)) {
    node.additionalProperties = false;
  }
  Object.values(node).forEach(closed);
}
closed(document.components.schemas);
closed(document.paths);
const ajv = new Ajv2020({ strict: false, allErrors: true });
ajv.addSchema(document, DOCUMENT_ID);

function loggedAnswers() {
  if (!LOG || !existsSync(LOG)) return [];
  const answers = [];
  for (const file of readdirSync(LOG).filter((f) => f.endsWith('.jsonl')).sort()) {
    for (const line of readFileSync(join(LOG, file), 'utf8').split('\n')) {
      if (line.trim()) answers.push({ test: file.replace(/\.jsonl$/, ''), ...JSON.parse(line) });
    }
  }
  return answers;
}

test('every answer the server tests got is as api/openapi.yaml says', { skip: !LOG && 'PHOTON_API_RESPONSE_LOG is not set' }, () => {
  const answers = loggedAnswers();
  assert.ok(answers.length > 500, `only ${answers.length} answers logged in ${LOG}: did the server tests run?`);
  const problems = new Set();
  let checkedBodies = 0;
  for (const a of answers) {
    const where = `${a.method} ${a.path} -> ${a.status} (in ${a.test})`;
    const found = operationFor(a.method, a.path);
    if (!found) {
      // Undocumented routes are answered 404/405, and the page's files are not the API.
      const isApi = a.path.startsWith('/api/') || a.path === '/metrics';
      if (isApi && ![404, 405].includes(a.status)) problems.add(`${where}: no such route in the document`);
      continue;
    }
    const { template, operation } = found;
    const response = resolved(
      operation.responses[String(a.status)] || document['x-photon-before-routing'][String(a.status)],
    );
    if (!response) {
      problems.add(`${a.method} ${template}: status ${a.status} is not documented (${where})`);
      continue;
    }
    if (!response.content || a.status === 304) continue;
    const mediaType = (a.content_type || '').split(';')[0].trim();
    const media = response.content[mediaType];
    if (!media) {
      problems.add(`${a.method} ${template} ${a.status}: content type "${mediaType}" is not one of ${Object.keys(response.content).join(', ')}`);
      continue;
    }
    if (a.body === undefined || !media.schema || !mediaType.endsWith('json')) continue;
    if (template === '/api/v1/info' && a.status === 200) {
      // The integrators the server offers are the ones the job schema names.
      const documented = document.components.schemas.Job.properties.settings.properties.integrator.enum;
      assert.deepEqual([...JSON.parse(a.body).integrators].sort(), [...documented].sort(), where);
    }
    const validate = validatorFor(template, a.method, a.status, mediaType, media.schema);
    if (!validate(JSON.parse(a.body))) {
      problems.add(`${a.method} ${template} ${a.status}: ${ajv.errorsText(validate.errors)} (${where})`);
    }
    checkedBodies++;
  }
  assert.deepEqual([...problems], [], `${problems.size} mismatches with api/openapi.yaml`);
  assert.ok(checkedBodies > 200, `only ${checkedBodies} bodies checked`);
});
