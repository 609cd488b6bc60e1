// The embed's two doors, fuzzed: seeded random messages (the API's types with random parameters,
// unknown types, things that are not messages at all) and random links. Values from outside come
// from a corpus of what breaks parsers and pages: names every object inherits, NaN spelled many
// ways, huge and tiny numbers, long and odd Unicode, and markup that would run script if it ever
// became HTML. FUZZ_SEED=<n> replays a run.
import { deflateSync } from 'fflate';
import { seededRandom } from '../../src/homework/seededRandom.js';

/** Markup that runs `window.__xss = 1` if it is ever parsed as HTML (or followed as a link). */
export const XSS = [
  '<img src=x onerror="window.__xss=1">',
  '<svg onload="window.__xss=1"></svg>',
  'javascript:window.__xss=1',
  '</textarea><script>window.__xss=1</script>',
  '"><img src=x onerror=window.__xss=1>',
  "'><svg/onload=window.__xss=1>",
  '<a href="javascript:window.__xss=1">link</a>',
];

export const PROTOTYPE_NAMES = ['constructor', 'toString', 'valueOf', 'hasOwnProperty', '__proto__', '__defineGetter__', 'isPrototypeOf', 'prototype'];

const ODD = ['NaN', 'nan', '+NaN', '-NaN', 'Infinity', '-Infinity', '1e999', '-1e999', '5e-324', '-0', '0x1', ' 1 ', '1_000', '1,5',
  '', ' ', '\u0000', 'e\u0301\u0301\u0301', '\u202eevil', '𝟙𝟚𝟛', 'a'.repeat(5000), 'true', 'TRUE', 'null', 'undefined', '#GGGGGG', '#12345'];

/** A value of any kind a deck or a link might send. */
function anyValue(rng) {
  switch (Math.floor(rng.next() * 9)) {
    case 0: return rng.pick([NaN, Infinity, -Infinity, 1e308, -1e308, 5e-324, -0, 0, 1, -1, 0.5, 2 ** 53]);
    case 1: return rng.next() * 200 - 100;
    case 2: return rng.pick(XSS);
    case 3: return rng.pick(ODD);
    case 4: return rng.pick([true, false, null]);
    case 5: return { toString: 'x', valueOf: 1 };
    case 6: return [1, 2, 3];
    case 7: return rng.pick(PROTOTYPE_NAMES);
    default: return String(rng.next());
  }
}

/** A key: one of the panel's, an inherited name, or markup. */
const anyKey = (rng, keys) => (rng.next() < 0.5 ? rng.pick(keys) : rng.pick([...PROTOTYPE_NAMES, ...XSS, 'nT.x', '']));

/**
 * `count` seeded messages for a panel whose schema keys are `keys`. Each is JSON text, parsed in
 * the page, so `__proto__` arrives as an own key, as it would from any other page.
 */
export function randomMessages(seed, keys, count) {
  const rng = seededRandom(seed);
  const params = () => {
    const entries = Array.from({ length: 1 + Math.floor(rng.next() * 4) }, () => [anyKey(rng, keys), anyValue(rng)]);
    return `{${entries.map(([k, v]) => `${JSON.stringify(k)}:${JSON.stringify(v) ?? 'null'}`).join(',')}}`;
  };
  const list = [];
  for (let i = 0; i < count; i += 1) {
    const type = JSON.stringify(`fresnel-lab:${rng.pick(['set', 'set', 'set', 'get', 'reset', 'lock', 'unlock', 'hide', 'show',
      'theme', 'projector', 'reducedMotion', 'pause', 'resume', 'snapshot', 'constructor', '__proto__', 'toString', 'evil'])}`);
    switch (Math.floor(rng.next() * 6)) {
      case 0: list.push(JSON.stringify(anyValue(rng)) ?? 'null'); break; // not a message at all
      case 1: list.push(`{"type":${type},"keys":[${JSON.stringify(anyKey(rng, keys))}]}`); break;
      case 2: list.push(`{"type":${type},"to":${JSON.stringify(anyValue(rng)) ?? 'null'},"theme":${JSON.stringify(anyValue(rng)) ?? 'null'}}`); break;
      default: list.push(`{"type":${type},"params":${params()}}`);
    }
  }
  return list;
}

/**
 * A value from the corpus that no spec of this type takes, by the type's own rules (docs/panels.md),
 * judged here and not by the page's parser: for a number, no decimal or one outside its range; for
 * an enum, none of its options; a colour not six hex digits; a boolean not true, false, 1 or 0; a
 * text longer than its cap, or a compact form that does not decode.
 */
function badValue(rng, spec) {
  const markup = rng.pick(XSS);
  switch (spec.type) {
    case 'number':
      return rng.pick([markup, 'NaN', '+NaN', 'Infinity', '-Infinity', '1e999', '0x1', '1,5', '1_000', '', 'e\u0301\u0301', '𝟙𝟚𝟛',
        String(spec.max + 1), String(spec.min - 1)]);
    case 'enum': {
      const options = Array.isArray(spec.options) ? spec.options.map(String) : Object.keys(spec.options);
      return rng.pick([markup, ...PROTOTYPE_NAMES, 'NaN', 'undefined', 'null', '', '\u202eevil'].filter((v) => !options.includes(v)));
    }
    case 'color':
      return rng.pick([markup, '#GGGGGG', '#12345', 'ff88001', 'red', '']);
    case 'boolean':
      return rng.pick([markup, 'TRUE', 'yes', '2', 'null', '']);
    default: {
      const long = markup.repeat(Math.ceil((spec.maxLength + 1) / markup.length));
      if (!spec.decode) return long;
      // The compact form (shader-lab/codeCodec.js; the plain text would pass a server's limit on a
      // request line): the over-long text deflated, 12 bytes stated before a stream that is not
      // base64, or an empty stream.
      const bytes = new TextEncoder().encode(long);
      return rng.pick([`*${bytes.length.toString(36)}.${Buffer.from(deflateSync(bytes)).toString('base64url')}`, '*c.A', '*1.']);
    }
  }
}

/** A link's query for a panel: every schema key with a bad value from the corpus, and a few keys that are not the panel's. */
export function randomQuery(seed, schema) {
  const rng = seededRandom(seed);
  const search = new URLSearchParams();
  const text = (v) => (v !== null && typeof v === 'object' ? JSON.stringify(v) : String(v)); // a link holds only text
  for (const [key, spec] of Object.entries(schema)) search.set(key, badValue(rng, spec));
  for (let i = 0; i < 3; i += 1) search.set(rng.pick([...PROTOTYPE_NAMES, ...XSS]), text(anyValue(rng)));
  return search.toString();
}

/** Posts the messages to the page itself (an embed opened alone hears its own window) and waits for each answer window. */
export async function sendMessages(page, messages) {
  await page.evaluate(async (list) => {
    for (const text of list) {
      window.postMessage(JSON.parse(text), '*');
      await new Promise((resolve) => { setTimeout(resolve, 0); });
    }
    await new Promise((resolve) => { requestAnimationFrame(() => requestAnimationFrame(resolve)); });
  }, messages);
}

/** Elements or attributes the corpus would have made, and whether its script ran. */
export const injected = (page) => page.evaluate(() => {
  const found = [...document.querySelectorAll('img[src="x"], script:not([src]):not([type="application/json"]), svg[onload], [onerror], [onload], a[href^="javascript:" i]')]
    .map((e) => e.outerHTML.slice(0, 80));
  if (window.__xss !== undefined) found.push('the sentinel script ran');
  return found;
});
