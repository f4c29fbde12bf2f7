// Where a value sits in JSON text, so the scene editor can select what a server error names.
// The server names it as a JSON Pointer ("/shapes/3/radius", RFC 6901) and as a path
// ("shapes[3].radius"); either is turned into keys and walked through the text itself, since
// JSON.parse keeps no positions.

// "/shapes/3/radius" -> ['shapes', '3', 'radius']
export function pointerKeys(pointer) {
  if (!pointer) return [];
  return pointer
    .split('/')
    .slice(1)
    .map((key) => key.replace(/~1/g, '/').replace(/~0/g, '~'));
}

// "shapes[3].radius" -> ['shapes', '3', 'radius']; null for what is not such a path (an
// imported scene's "scene.pbrt:12").
export function pathKeys(path) {
  if (typeof path !== 'string' || !/^([A-Za-z_][\w-]*|\[\d+\])(\.[A-Za-z_][\w-]*|\[\d+\])*$/.test(path)) return null;
  return [...path.matchAll(/[A-Za-z_][\w-]*|\[(\d+)\]/g)].map((m) => m[1] ?? m[0]);
}

// The place of the value at `keys` in `text`: { start, end } of the member ("key": value) or
// array element, and how many of the keys were found. Keys the text does not have (a value
// the form wrote into the scene it sent) stop the walk at the deepest one it has. null for
// text that is not JSON enough to walk.
export function locateValue(text, keys) {
  let i = 0;
  const ws = () => {
    while (i < text.length && ' \t\n\r'.includes(text[i])) i++;
  };
  const fail = () => {
    throw new Error('not JSON');
  };

  function skipString() {
    if (text[i] !== '"') fail();
    i++;
    while (i < text.length && text[i] !== '"') i += text[i] === '\\' ? 2 : 1;
    if (i >= text.length) fail();
    i++;
  }

  function readString() {
    const start = i;
    skipString();
    return JSON.parse(text.slice(start, i));
  }

  // Skips one value; returns its end.
  function skipValue() {
    ws();
    const ch = text[i];
    if (ch === '"') skipString();
    else if (ch === '{' || ch === '[') {
      const close = ch === '{' ? '}' : ']';
      i++;
      ws();
      if (text[i] === close) {
        i++;
      } else {
        for (;;) {
          if (close === '}') {
            ws();
            skipString();
            ws();
            if (text[i] !== ':') fail();
            i++;
          }
          skipValue();
          ws();
          if (text[i] === ',') {
            i++;
            continue;
          }
          if (text[i] !== close) fail();
          i++;
          break;
        }
      }
    } else {
      const match = /^(-?[\d.eE+-]+|true|false|null)/.exec(text.slice(i, i + 400));
      if (!match) fail();
      i += match[0].length;
    }
    return i;
  }

  // Finds the child `key` of the value starting at i; leaves i at the child's value and
  // returns the start of its member or element, or -1 if there is no such child.
  function child(key) {
    ws();
    const ch = text[i];
    if (ch !== '{' && ch !== '[') return -1;
    const isObject = ch === '{';
    i++;
    for (let index = 0; ; index++) {
      ws();
      if (text[i] === '}' || text[i] === ']') return -1;
      const memberStart = i;
      let name = String(index);
      if (isObject) {
        name = readString();
        ws();
        if (text[i] !== ':') fail();
        i++;
      }
      ws();
      if (name === key) return memberStart;
      skipValue();
      ws();
      if (text[i] === ',') i++;
      else return -1;
    }
  }

  try {
    ws();
    let place = { start: i, end: -1, found: 0 };
    for (const key of keys) {
      const valueOf = i;
      const start = child(key);
      if (start < 0) {
        i = valueOf;
        break;
      }
      place = { start, end: -1, found: place.found + 1 };
    }
    ws();
    place.end = skipValue();
    return place;
  } catch {
    return null;
  }
}
