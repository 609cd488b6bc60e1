// A lecture from anyone: read from any JSON without throwing, every part kept valid or named; a
// lecture written to a link reads back as the same lecture; a damaged code is refused; and the
// lecturer's Markdown gives only the allowed kinds of node, links only to http(s) and mailto.
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { readLecture, LECTURE_CAPS, LECTURE_KIND } from '../../src/lecture/readLecture.js';
import { lectureFromCode, lectureToCode } from '../../src/lecture/lectureLink.js';
import { lectureCodeLanguage } from '../../src/lecture/lectureCode.js';
import { lectureTextTree } from '../../src/lecture/lectureText.js';
import { defaultLecture } from '../../src/lecture/defaultLecture.js';
import { PANELS } from '../../src/panels/manifest.js';
import { panelSchema } from '../../src/panels/panelSchema.js';
import { parseValue } from '../../src/host/params.js';
import { QUESTIONS } from '../../src/homework/questions.js';
import { anyJson, anyKey, anyText, anyValue, ownObject } from './fuzzArbitraries.js';
import { check } from './fuzzConfig.js';

/** A value the spec may or may not take: its own kinds, its edges, and anything. */
function valueFor(spec) {
  const own = spec.type === 'number' ? fc.oneof(fc.double({ min: spec.min, max: spec.max, noNaN: true }), fc.constantFrom(spec.min, spec.max, spec.default))
    : spec.type === 'enum' ? fc.constantFrom(...Object.keys(spec.options)) : spec.type === 'boolean' ? fc.boolean() : fc.string({ maxLength: 40 });
  return fc.oneof({ weight: 4, arbitrary: own }, { weight: 1, arbitrary: anyValue });
}

const panelItem = fc.constantFrom(...PANELS.map((p) => p.id)).chain((id) => {
  const schema = panelSchema(id);
  const keys = Object.keys(schema);
  return fc.record({
    type: fc.constant('panel'), panel: fc.constant(id),
    state: fc.array(fc.constantFrom(...keys), { maxLength: 4 }).chain((ks) => fc.tuple(...ks.map((k) => valueFor(schema[k]).map((v) => [k, v])))).map(ownObject),
    lock: fc.subarray(keys, { maxLength: Math.min(3, keys.length) }), hide: fc.subarray(keys, { maxLength: Math.min(2, keys.length) }),
    heading: fc.string({ unit: 'grapheme', maxLength: 40 }), text: fc.string({ unit: 'grapheme', maxLength: 200 }),
  }, { requiredKeys: ['type', 'panel'] });
});
const textItem = fc.record({ type: fc.constant('text'), heading: fc.string({ maxLength: 30 }), text: fc.string({ unit: 'grapheme', minLength: 1, maxLength: 300 }) }, { requiredKeys: ['type', 'text'] });
const questionItem = fc.record({ type: fc.constant('question'), question: fc.constantFrom(...QUESTIONS.map((q) => q.id)), seed: fc.string({ maxLength: 20 }), text: fc.string({ maxLength: 50 }) }, { requiredKeys: ['type', 'question'] });
const lectureData = fc.record({
  kind: fc.constant(LECTURE_KIND), version: fc.constant(1), title: fc.string({ unit: 'grapheme', maxLength: 60 }),
  lang: fc.oneof(fc.constantFrom('en', 'es', 'en-XA', 'ar-XB', 'EN', 'es-MX', 'xx', ''), anyValue),
  items: fc.array(fc.oneof(panelItem, panelItem, textItem, questionItem, anyJson), { maxLength: 12 }),
}, { requiredKeys: ['kind', 'version', 'title', 'items'] });

/** A read lecture is valid: real panels and questions, values its schema takes, keys it has, text within its caps. */
function expectValid(lecture) {
  expect(lecture.items.length).toBeLessThanOrEqual(LECTURE_CAPS.items);
  expect(lecture.title.length).toBeLessThanOrEqual(LECTURE_CAPS.title);
  expect(lecture.lang === undefined || ['en', 'es', 'en-XA', 'ar-XB'].includes(lecture.lang)).toBe(true);
  for (const item of lecture.items) {
    if (item.type === 'panel') {
      const schema = panelSchema(item.panel);
      for (const [key, value] of Object.entries(item.state ?? {})) expect(parseValue(schema[key], value), `${item.panel}.${key}`).toEqual({ ok: true, value });
      for (const key of [...(item.lock ?? []), ...(item.hide ?? [])]) expect(Object.hasOwn(schema, key)).toBe(true);
    } else if (item.type === 'question') expect(QUESTIONS.some((q) => q.id === item.question)).toBe(true);
    else expect(item.type).toBe('text');
    expect((item.text ?? '').length).toBeLessThanOrEqual(LECTURE_CAPS.text);
  }
}

describe('a lecture read from untrusted data', () => {
  it('never throws: a lecture whose every part is valid, with what was left out named, or refused with reasons', () => {
    check(fc.property(fc.oneof(lectureData, anyValue, anyJson, fc.array(fc.tuple(anyKey, anyJson)).map(ownObject)), (data) => {
      const read = readLecture(data);
      expect(read.problems.every((p) => typeof p === 'string' && p.length > 0)).toBe(true);
      if (read.ok) expectValid(read.lecture);
      else expect(read.problems.length).toBeGreaterThan(0);
    }), 300);
  });

  it('an unknown panel, question, key or kind of item is named, and the rest of the lecture is kept', () => {
    const read = readLecture({
      kind: LECTURE_KIND, version: 1, title: 'Mine', extra: 1,
      items: [{ type: 'panel', panel: 'constructor' }, { type: 'panel', panel: 'schlick', state: { nT: 2, bogus: 1 }, lock: ['toString'] },
        { type: 'question', question: '__proto__' }, { type: 'slide' }, { type: 'text', text: 'Agenda' }],
    });
    expect(read.ok).toBe(true);
    expect(read.lecture.items).toEqual([{ type: 'panel', panel: 'schlick', state: { nT: 2 } }, { type: 'text', text: 'Agenda' }]);
    for (const name of ['extra', 'constructor', 'bogus', 'toString', '__proto__', 'slide']) expect(read.problems.join('\n')).toContain(name);
  });
});

describe('the language a lecture was written in', () => {
  const lecture = (lang) => ({ kind: LECTURE_KIND, version: 1, title: 'Óptica', lang, items: [{ type: 'text', text: 'Agenda' }] });

  it('is kept when the lab speaks it (a pseudo-locale too), and goes through a link', () => {
    for (const lang of ['en', 'es', 'en-XA', 'ar-XB']) {
      const read = readLecture(lecture(lang));
      expect(read, lang).toEqual({ ok: true, lecture: lecture(lang), problems: [] });
      expect(lectureFromCode(lectureToCode(read.lecture)).lecture.lang).toBe(lang);
    }
    expect(readLecture({ ...lecture('en'), lang: undefined }).lecture).not.toHaveProperty('lang');
  });

  it('is named and left out when the lab does not speak it, and the rest of the lecture opens', () => {
    for (const [i, lang] of ['xx', 'es-MX', 'EN', '', 42, { toString: 'x' }, ['es']].entries()) {
      const read = readLecture(lecture(lang));
      expect(read.ok, `case ${i}`).toBe(true);
      expect(read.lecture).not.toHaveProperty('lang');
      expect(read.lecture.items).toEqual([{ type: 'text', text: 'Agenda' }]);
      expect(read.problems).toHaveLength(1);
      expect(read.problems[0]).toMatch(/^The language .* is not one the lab speaks \(en, es\), so it is left out\.$/);
    }
    expect(readLecture(lecture('xx')).problems[0]).toContain('xx');
  });

  it('is read from a code or a link before the lecture is, as readLecture would keep it', () => {
    const code = (lang) => lectureToCode(lecture(lang));
    for (const lang of ['en', 'es', 'en-XA', 'ar-XB']) {
      expect(lectureCodeLanguage(code(lang)), lang).toBe(lang);
      expect(lectureCodeLanguage(`https://lab.example/index.html?lecture=${encodeURIComponent(code(lang))}&x=1`)).toBe(lang);
    }
    for (const lang of ['xx', 'es-MX', 42, undefined]) expect(lectureCodeLanguage(code(lang)), String(lang)).toBeNull();
    // Whatever the text, a language the lab speaks or null, never a throw.
    check(fc.property(fc.oneof(anyText, anyText.map((t) => `L1.${t}`), anyValue), (text) => {
      const lang = lectureCodeLanguage(text);
      expect(lang === null || ['en', 'es', 'en-XA', 'ar-XB'].includes(lang)).toBe(true);
    }), 200);
  });
});

describe('a lecture in a link', () => {
  it('lecture → link → lecture is the identity', () => {
    check(fc.property(lectureData, (data) => {
      const { lecture } = readLecture(data);
      expect(readLecture(lecture)).toEqual({ ok: true, lecture, problems: [] }); // reading a read lecture changes nothing
      expect(lectureFromCode(lectureToCode(lecture))).toEqual({ ok: true, lecture, problems: [] });
      const link = `https://lab.example/index.html?lecture=${encodeURIComponent(lectureToCode(lecture))}#spheres`;
      expect(lectureFromCode(link).lecture).toEqual(lecture);
    }), 100);
  });

  it('the default lecture is every panel in the lecture\'s order and survives a link', () => {
    const lecture = defaultLecture();
    expect(lecture.items.map((i) => i.panel)).toEqual(PANELS.map((p) => p.id));
    expect(lectureFromCode(lectureToCode(lecture))).toEqual({ ok: true, lecture, problems: [] });
    expect(lectureToCode(lecture).length).toBeLessThan(400);
  });

  it('a code cut, changed or made up is refused with a reason or read as a valid lecture, never thrown', () => {
    const damaged = fc.tuple(lectureData, fc.nat(), fc.nat(), fc.constantFrom('cut', 'change', 'wrap')).map(([data, a, b, how]) => {
      const code = lectureToCode(readLecture(data).lecture);
      const at = 3 + (a % Math.max(1, code.length - 3));
      if (how === 'cut') return code.slice(0, at);
      if (how === 'wrap') return `${code.slice(0, at)}\n  ${code.slice(at)}`;
      return code.slice(0, at) + 'AZaz09-_'[b % 8] + code.slice(at + 1);
    });
    check(fc.property(fc.oneof(damaged, anyText, anyText.map((t) => `L1.${t}`), anyValue), (code) => {
      const read = lectureFromCode(code);
      if (read.ok) expectValid(read.lecture);
      else expect(read.problems[0]).toMatch(/\S/);
    }), 300);
  });
});

describe('the lecturer\'s Markdown', () => {
  const TAGS = ['p', 'ul', 'ol', 'li', 'em', 'strong', 'code', 'br', 'a'];
  const XSS = ['<img src=x onerror=alert(1)>', '<svg onload=alert(1)>', '[x](javascript:alert(1))', '[x](JAVASCRIPT:alert(1))', '[x]( javascript:alert(1))',
    '[x](data:text/html,<script>alert(1)</script>)', '[x](vbscript:msgbox)', '<a href="javascript:alert(1)">x</a>', '![x](https://evil.example/t.png)',
    '<script>alert(1)</script>', '</textarea><script>alert(1)</script>', '"><img src=x onerror=alert(1)>', '[x](//evil.example)', '[x](/relative)',
    '$\\href{javascript:alert(1)}{x}$', '<style>*{display:none}</style>', '<iframe src="https://evil.example"></iframe>',
    '[x]()', '[]()', '[x]( )', '[x](<>)'];

  /** Every node in the tree: only allowed tags, links only to http(s) and mailto, text as text. */
  function expectSafe(nodes) {
    for (const node of nodes) {
      if ('text' in node || 'math' in node) continue;
      expect(TAGS).toContain(node.tag);
      if (node.tag === 'a') expect(node.href).toMatch(/^(https?:|mailto:)/i);
      expect(Object.keys(node).every((k) => ['tag', 'href', 'start', 'children'].includes(k))).toBe(true);
      expectSafe(node.children);
    }
  }

  it('an XSS corpus gives text, never an element, an image or a script link', () => {
    for (const source of XSS) {
      const tree = lectureTextTree(source);
      expectSafe(tree);
      expect(JSON.stringify(tree)).not.toMatch(/"href":"(?!https?:|mailto:)/i);
    }
    expect(lectureTextTree('<img src=x onerror=alert(1)>')).toEqual([{ tag: 'p', children: [{ text: '<img src=x onerror=alert(1)>' }] }]);
    // A link with no target (markdown-it checks none) keeps its words, as text.
    expect(lectureTextTree('see [x]() here')).toEqual([{ tag: 'p', children: [{ text: 'see ' }, { text: 'x' }, { text: ' here' }] }]);
  });

  it('what it is for: paragraphs, emphasis, lists, links and math', () => {
    expect(lectureTextTree('*R* at **θ** [see](https://x.example) and $R_0$\n\n- a\n- b\n\n$$\\theta_B$$')).toEqual([
      { tag: 'p', children: [{ tag: 'em', children: [{ text: 'R' }] }, { text: ' at ' }, { tag: 'strong', children: [{ text: 'θ' }] }, { text: ' ' },
        { tag: 'a', href: 'https://x.example', children: [{ text: 'see' }] }, { text: ' and ' }, { math: 'R_0', display: false }] },
      { tag: 'ul', children: [{ tag: 'li', children: [{ text: 'a' }] }, { tag: 'li', children: [{ text: 'b' }] }] },
      { math: '\\theta_B', display: true },
    ]);
  });

  it('any text gives only allowed nodes', () => {
    const pieces = fc.constantFrom(...XSS, '*', '**', '_', '`', '$', '$$', '[', ']', '(', ')', '\n', '\n\n', '- ', '1. ', '> ', '# ', 'http://x.example', 'mailto:a@b.c', 'text');
    check(fc.property(fc.oneof(fc.array(pieces, { maxLength: 20 }).map((p) => p.join('')), anyText), (source) => expectSafe(lectureTextTree(source))), 300);
  });
});
