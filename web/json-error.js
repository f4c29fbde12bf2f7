// Explains why a text is not valid JSON, in plain words with a line and column. Browsers
// word JSON.parse errors differently and do not always say where the problem is, so
// locateJsonError() scans the text itself (a strict JSON grammar check, RFC 8259).

// Returns null if `text` is valid JSON, else { offset, reason }.
export function locateJsonError(text) {
  let i = 0;
  const fail = (reason, at = i) => {
    throw { offset: at, reason };
  };
  const ws = () => {
    while (i < text.length && ' \t\n\r'.includes(text[i])) i++;
  };
  const describe = (ch) => (ch === undefined ? 'the end of the text' : `'${ch}'`);

  function value() {
    ws();
    const ch = text[i];
    if (ch === '{') return object();
    if (ch === '[') return array();
    if (ch === '"') return string();
    if (ch === '-' || (ch >= '0' && ch <= '9')) return number();
    for (const word of ['true', 'false', 'null']) {
      if (text.startsWith(word, i)) {
        i += word.length;
        return;
      }
    }
    if (ch === undefined) fail('the text ends where a value was expected');
    fail(`expected a value (object, array, string, number, true, false or null) but found ${describe(ch)}`);
  }

  function object() {
    i++; // {
    ws();
    if (text[i] === '}') {
      i++;
      return;
    }
    for (;;) {
      ws();
      if (text[i] !== '"') fail(`expected a property name in double quotes but found ${describe(text[i])}`);
      string();
      ws();
      if (text[i] !== ':') fail(`expected ':' after the property name but found ${describe(text[i])}`);
      i++;
      value();
      ws();
      if (text[i] === ',') {
        i++;
        ws();
        if (text[i] === '}') fail("a trailing comma before '}' is not allowed in JSON");
        continue;
      }
      if (text[i] === '}') {
        i++;
        return;
      }
      fail(`expected ',' or '}' after a property but found ${describe(text[i])}`);
    }
  }

  function array() {
    i++; // [
    ws();
    if (text[i] === ']') {
      i++;
      return;
    }
    for (;;) {
      value();
      ws();
      if (text[i] === ',') {
        i++;
        ws();
        if (text[i] === ']') fail("a trailing comma before ']' is not allowed in JSON");
        continue;
      }
      if (text[i] === ']') {
        i++;
        return;
      }
      fail(`expected ',' or ']' after an array element but found ${describe(text[i])}`);
    }
  }

  function string() {
    const start = i;
    i++; // opening quote
    for (;;) {
      const ch = text[i];
      if (ch === undefined) fail('a string is not closed (missing \'"\')', start);
      if (ch === '"') {
        i++;
        return;
      }
      if (ch < ' ') fail('a line break or control character inside a string (use \\n)');
      if (ch === '\\') {
        const next = text[i + 1];
        if (next === 'u') {
          if (!/^[0-9a-fA-F]{4}$/.test(text.slice(i + 2, i + 6))) fail('\\u must be followed by four hex digits');
          i += 6;
          continue;
        }
        if (next === undefined || !'"\\/bfnrt'.includes(next)) fail(`unknown escape \\${next ?? ''} in a string`);
        i += 2;
        continue;
      }
      i++;
    }
  }

  function number() {
    const match = /^-?(0|[1-9]\d*)(\.\d+)?([eE][+-]?\d+)?/.exec(text.slice(i, i + 400));
    if (!match || match[0] === '-') fail('a number is malformed');
    i += match[0].length;
  }

  try {
    value();
    ws();
    if (i < text.length) fail(`unexpected ${describe(text[i])} after the end of the JSON value`);
    return null;
  } catch (error) {
    if (error && typeof error.offset === 'number') return error;
    throw error;
  }
}

// 0-based character offset -> 1-based { line, column }.
export function lineAndColumn(text, offset) {
  const before = text.slice(0, Math.max(0, Math.min(offset, text.length)));
  const lines = before.split('\n');
  return { line: lines.length, column: lines[lines.length - 1].length + 1 };
}

// The message shown next to the scene textarea. `parseError` is what JSON.parse threw.
export function describeJsonError(text, parseError) {
  if (text.trim() === '') return 'The scene is empty: choose an example, load a file or paste scene JSON.';
  const found = locateJsonError(text);
  if (found) {
    const { line, column } = lineAndColumn(text, found.offset);
    return `The scene is not valid JSON: ${found.reason} at line ${line}, column ${column}.`;
  }
  // The scanner and the browser disagree (should not happen): report the browser's words.
  let words = String((parseError && parseError.message) || parseError || 'unknown problem');
  const at = /at position (\d+)/.exec(words);
  words = words.replace(/\s*\(line \d+ column \d+\)/, '').replace(/\s*(in JSON )?at position \d+/, '');
  if (!at) return `The scene is not valid JSON: ${words}.`;
  const { line, column } = lineAndColumn(text, Number(at[1]));
  return `The scene is not valid JSON: ${words} at line ${line}, column ${column}.`;
}
