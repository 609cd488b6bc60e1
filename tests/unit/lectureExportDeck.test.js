// The reveal.js deck export: one slide per item in the lecture's order; each panel's frame is the
// embed page with the item's state, locks and hidden controls; WebGL panels load only on their
// slide; and nothing from the lecture (title, headings, texts) becomes markup: every tag and
// attribute of the slides is one the deck writes, every link http(s) or mailto.
// (Under vitest a CSS file imported with ?raw is empty, so reveal.js's CSS is not checked here; the
// browser test, tests/e2e/lectureExport.spec.js, runs the real deck.)
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { DEFAULT_EMBED_URL, lectureDeckHtml } from '../../src/lecture/deckExport.js';
import { DEFAULT_QUESTION_SEED, embedSource } from '../../src/lecture/deckSlides.js';
import { subscriptedHtml } from '../../src/lecture/lectureTextHtml.js';
import { escapeHtml } from '../../src/ui/escapeHtml.js';
import { LECTURE_KIND, readLecture } from '../../src/lecture/readLecture.js';
import { PANELS, panelEntry } from '../../src/panels/manifest.js';
import { panelSchema } from '../../src/panels/panelSchema.js';
import { defaults, readParams } from '../../src/host/params.js';
import { readEmbedOptions } from '../../src/host/readEmbedOptions.js';
import { QUESTIONS } from '../../src/homework/questions.js';
import { expectedValue, questionParams, trueOption } from '../../src/homework/gradeAnswer.js';
import { formatValue } from '../../src/homework/formatAnswer.js';
import { check } from './fuzzConfig.js';
import spanish from 'virtual:messages/es';
import { setCatalogue } from '../../src/i18n/messages.js';

const XSS = ['</script><script>alert(1)</script>', '<img src=x onerror=alert(1)>', '"><svg onload=alert(1)>', "'><svg/onload=alert(1)>",
  '[x](javascript:alert(1))', '[x]( JAVASCRIPT:alert(1))', '[x](data:text/html,<script>alert(1)</script>)',
  '<a href="javascript:alert(1)">x</a>', '![x](https://evil.example/t.png)', '<style>*{display:none}</style>',
  '<iframe src="https://evil.example"></iframe>', '<!--', '-->', '$\\href{javascript:alert(1)}{x}$', '$\\htmlClass{x}{y}$',
  '$$\\url{javascript:alert(1)}$$', '[x](https://a.example/"onmouseover="alert(1))', '&lt;script&gt;', '&#60;script&#62;',
  '$\\fcolorbox{red}{blue}{x}$', '$\\color{#f00"onload}x$', '</section></div><script>alert(1)</script>', '{{7*7}}', '\u2028',
  'n_t <b>bold</b>', '[x]()', '[]()', '[x]( )', '[x](<>)'];
const MARKDOWN_BITS = ['*', '_', '`', '$', '$$', '[', '](', ')', '\n\n', '- ', 'https://x.example', 'mailto:a@b.c', '<', '"', "'", '&'];

const STAND_IN = { revealJs: 'window.Reveal = function () { return { initialize() {} }; };', revealCss: '.reveal{}' };
const deck = (lecture, options = {}) => lectureDeckHtml(lecture, { ...STAND_IN, ...options });
const lectureOf = (items, title = 'A lecture') => ({ kind: LECTURE_KIND, version: 1, title, items });

/** The text of the five entities escapeHtml writes, back to characters. */
const unescape = (text) => text.replace(/&(amp|lt|gt|quot|#39);/g, (_, e) => ({ amp: '&', lt: '<', gt: '>', quot: '"', '#39': "'" })[e]);
/** The slides' markup: between <div class="slides"> and the deck's scripts. */
const slidesOf = (html) => html.slice(html.indexOf('<div class="slides">'), html.indexOf('<script>'));

const TAG = /<(\/?)([a-zA-Z][a-zA-Z0-9-]*)((?:\s+[a-zA-Z][a-zA-Z0-9:-]*(?:="[^"<>]*")?)*)\s*(\/?)>/g;
const HTML_TAGS = ['div', 'section', 'h1', 'h2', 'p', 'ul', 'ol', 'li', 'em', 'strong', 'code', 'br', 'a', 'sub', 'span', 'iframe',
  'svg', 'path', 'line']; // the last three: KaTeX's drawn delimiters, roots and lines
/** KaTeX's layout (its HTML output): lengths, colours and borders it computed, never a url() or any call. */
const KATEX_STYLE = new Set(['height', 'vertical-align', 'margin-right', 'top', 'margin-left', 'border-bottom-width', 'left',
  'padding-left', 'min-width', 'color', 'border', 'border-style', 'border-width', 'background-color', 'border-color', 'width',
  'position']);
const katexStyle = (value) => value.split(';').filter(Boolean).every((declaration) => {
  const [property, ...rest] = declaration.split(':');
  return KATEX_STYLE.has(property.trim()) && /^[-#\w.% ]+$/.test(rest.join(':').trim());
});
const isMathTag = (tag) => /^(math|semantics|annotation|m[a-z]+)$/.test(tag);

/**
 * Every < of the slides opens or closes a tag the deck writes, with attributes it writes: no event
 * handler, no style, no src; a link only to http(s) or mailto, a frame only from the embed page.
 */
function expectOnlyDeckMarkup(html, embedUrl = DEFAULT_EMBED_URL) {
  const slides = slidesOf(html);
  const tags = [...slides.matchAll(TAG)];
  expect(tags.length, 'every < is a tag of the deck').toBe((slides.match(/</g) ?? []).length);
  for (const [, , name, attributes] of tags) {
    const tag = name.toLowerCase();
    expect(HTML_TAGS.includes(tag) || isMathTag(tag), tag).toBe(true);
    for (const [, attribute, value = ''] of attributes.matchAll(/\s([a-zA-Z][a-zA-Z0-9:-]*)(?:="([^"]*)")?/g)) {
      const key = attribute.toLowerCase();
      expect(key, `${tag} ${key}`).not.toMatch(/^(on|src$|srcdoc$|formaction$)/);
      // KaTeX's own layout and its frame of \fcolorbox, colours checked by KaTeX; no other style.
      if (key === 'style') expect(katexStyle(value), `${tag} style="${value}"`).toBe(true);
      if (key === 'href') {
        expect(tag).toBe('a');
        expect(unescape(value)).toMatch(/^(https?:|mailto:)/i);
      }
      if (key === 'data-src') expect(unescape(value).startsWith(`${embedUrl}?panel=`), value).toBe(true);
    }
  }
}

/** The data-src of each frame, read as the embed page reads its link. */
function framesOf(html) {
  return [...slidesOf(html).matchAll(/<iframe([^>]*)>/g)].map(([, attributes]) => {
    const src = unescape(/data-src="([^"]*)"/.exec(attributes)[1]);
    return { src, preload: / data-preload/.test(attributes), search: new URLSearchParams(src.slice(src.indexOf('?') + 1)) };
  });
}

const composed = lectureOf([
  { type: 'text', heading: 'Agenda', text: '1. Into glass\n2. Out of it\n\nSee [the book](https://book.example) and $R_0$.' },
  { type: 'panel', panel: 'spheres', state: { nT: 1.5 }, heading: 'Into glass' },
  { type: 'panel', panel: 'spheres', state: { nI: 1.5, nT: 1 }, lock: ['nI'], hide: ['kd', 'ks'], text: 'Out of it: $\\theta_c$.' },
  { type: 'question', question: 'brewster-predict', seed: 'room 12' },
  { type: 'panel', panel: 'schlick', state: { nT: 1.7 } },
], 'Glass, twice');

describe('the reveal.js deck of a lecture', () => {
  it('has a title slide and then one slide per item, in order, a question with its answer below', () => {
    const html = deck(composed);
    const items = [...slidesOf(html).matchAll(/<section[^>]* data-item="(\d+)" data-item-type="(\w+)"/g)]
      .map(([, n, type]) => [Number(n), type]);
    expect(items).toEqual([[1, 'text'], [2, 'panel'], [3, 'panel'], [4, 'question'], [5, 'panel']]);
    expect(slidesOf(html).match(/<section/g)).toHaveLength(1 + 5 + 2); // the title, the items, the question's two
    expect(html).toContain('<h1>Glass, twice</h1>');
    expect(html).toContain('<title>Glass, twice</title>');
    expect(html).toContain('<h2>Into glass</h2>');
    // No heading of the lecturer's: no slide heading, the embed shows the panel's title (not twice).
    expect(html).not.toContain(`<h2>${subscriptedHtml(panelEntry('schlick').title)}</h2>`);
    expect(html).toMatch(/data-panel="schlick">\s*<iframe/);
    // The lecturer's Markdown as HTML: the list, the paragraph, the link opening elsewhere, the math.
    expect(html).toContain('<ol><li>Into glass</li><li>Out of it</li></ol><p>See <a href="https://book.example" target="_blank" '
      + 'rel="noopener noreferrer">the book</a> and <span class="lecture-math">');
    expect(html).toContain('<a href="https://book.example" target="_blank" rel="noopener noreferrer">the book</a>');
    // KaTeX's HTML, as on the site, with MathML for screen readers; the deck then carries KaTeX's CSS and fonts.
    expect(html).toMatch(/<span class="lecture-math"><span class="katex"><span class="katex-mathml"><math [^>]*>.*<annotation encoding="application\/x-tex">R_0</);
    expect(html).toMatch(/<span class="katex-html" aria-hidden="true">/);
    expect(html).toMatch(/font-family:KaTeX_Main;[^}]*src:url\(data:font\/woff2;base64,[A-Za-z0-9+/=]+\) format\("woff2"\)/);
    expect(html).not.toMatch(/url\(fonts\//); // no font left to fetch from beside the file
    expectOnlyDeckMarkup(html);
  });

  it('each panel frame is the embed page with the item\'s state, locks and hidden controls, read back as the embed reads them', () => {
    const frames = framesOf(deck(composed, { projector: true }));
    const brewster = QUESTIONS.find((q) => q.id === 'brewster-predict');
    const expected = [
      [composed.items[1], 'spheres'], [composed.items[2], 'spheres'],
      [{ state: brewster.state(questionParams(brewster, 'room 12')) }, 'polarization'],
      [composed.items[4], 'schlick'],
    ];
    expect(frames).toHaveLength(expected.length);
    frames.forEach(({ search }, i) => {
      const [item, id] = expected[i];
      expect(search.get('panel')).toBe(id);
      const { values, problems } = readParams(panelSchema(id), search);
      expect(problems).toEqual([]);
      expect(values).toEqual({ ...defaults(panelSchema(id)), ...item.state });
      const { options, problems: embedProblems } = readEmbedOptions(search);
      expect(embedProblems).toEqual([]);
      expect(options).toMatchObject({ lock: item.lock ?? [], hide: item.hide ?? [], theme: 'dark', projector: true });
    });
    expect(frames[0].src).toBe('offline/embed.html?panel=spheres&theme=dark&projector=1&fit=1'); // nT = 1.5 is the default: not written
    expect(frames[1].src).toBe('offline/embed.html?panel=spheres&nI=1.5&nT=1&lock=nI&hide=kd,ks&theme=dark&projector=1&fit=1');
  });

  it('speaks the lecture\'s language: the page\'s lang and dir, and every panel frame\'s lang=', () => {
    for (const [lang, dir] of [['es', 'ltr'], ['ar-XB', 'rtl']]) {
      const html = deck({ ...composed, lang });
      expect(html).toContain(`<html lang="${lang}" dir="${dir}">`);
      const frames = framesOf(html);
      expect(frames.length).toBeGreaterThan(0);
      for (const frame of frames) expect(frame.search.get('lang'), frame.src).toBe(lang);
    }
    // A lecture without a language: the deck in the words it is written in, its panels in their reader's.
    expect(deck(composed)).toContain('<html lang="en" dir="ltr">');
    expect(framesOf(deck(composed)).every((frame) => !frame.search.has('lang'))).toBe(true);
  });

  it('a WebGL panel loads only on its slide; a plot-only panel, which holds no context, is preloaded', () => {
    const lecture = lectureOf(PANELS.map(({ id }) => ({ type: 'panel', panel: id })));
    const frames = framesOf(deck(lecture));
    expect(frames.map((f) => f.search.get('panel'))).toEqual(PANELS.map((p) => p.id));
    // Whether a panel opens a context, always or at times, is its manifest entry's (manifest.test.js checks it against its code).
    frames.forEach(({ preload }, i) => expect(preload, PANELS[i].id).toBe(!PANELS[i].webgl && !PANELS[i].webglAtTimes));
    expect(PANELS.some((p) => p.webgl) && PANELS.some((p) => p.webglAtTimes) && PANELS.some((p) => !p.webgl && !p.webglAtTimes)).toBe(true);
  });

  it('embedUrl: the site\'s own embed page, or one beside the deck; never a script or data URL', () => {
    const online = 'https://lab.example/fresnel-lab/embed.html';
    const html = deck(composed, { embedUrl: online, theme: null });
    expect(framesOf(html).every((f) => f.src.startsWith(`${online}?panel=`) && !f.search.has('theme'))).toBe(true);
    expectOnlyDeckMarkup(html, online);
    expect(framesOf(deck(composed, { embedUrl: 'embed.html?x=1' }))[0].src).toBe('embed.html?x=1&panel=spheres&theme=dark&fit=1');
    for (const bad of ['javascript:alert(1)', ' JavaScript:alert(1)', 'data:text/html,x', '', '  ', 42]) {
      expect(() => deck(composed, { embedUrl: bad }), String(bad)).toThrow(/embedUrl/);
    }
    expect(() => deck(composed, { theme: 'pink' })).toThrow(/theme/);
    expect(deck(composed, { theme: 'light' })).toContain('--r-background-color: #fff');
    expect(deck(composed)).not.toContain('--r-background-color: #fff');
    expect(() => deck({ kind: 'nope' })).toThrow(/no lecture/);
  });

  it('an XSS corpus in the title, headings and texts stays text', () => {
    for (const bad of XSS) {
      const lecture = lectureOf([
        { type: 'text', heading: bad, text: bad },
        { type: 'panel', panel: 'metals', heading: bad, text: `${bad}\n\n- ${bad}\n- *${bad}*` },
        { type: 'question', question: 'r0-value', heading: bad, text: bad, seed: bad },
      ], bad);
      const html = deck(lecture);
      expectOnlyDeckMarkup(html);
      const read = readLecture(lecture).lecture;
      expect(html).toContain(`<title>${escapeHtml(read.title)}</title>`);
      expect(html).toContain(`<h1>${escapeHtml(read.title)}</h1>`);
      const headings = [...slidesOf(html).matchAll(/<h2>([^<]*)<\/h2>/g)].map(([, text]) => unescape(text));
      for (const item of read.items) if (item.heading) expect(headings, bad).toContain(item.heading); // a heading of spaces is left out
      expect(html.match(/<script>/g)).toHaveLength(2); // reveal.js and the deck's lines, nothing more
    }
  });

  it('any lecture gives only the deck\'s markup, a slide per item', () => {
    const text = fc.oneof(fc.string({ unit: 'grapheme', maxLength: 80 }), fc.constantFrom(...XSS),
      fc.array(fc.constantFrom(...XSS, ...MARKDOWN_BITS), { maxLength: 10 }).map((p) => p.join('')));
    const ids = (list) => fc.constantFrom(...list.map((x) => x.id));
    const item = fc.oneof(
      fc.record({ type: fc.constant('text'), heading: text, text }),
      fc.record({ type: fc.constant('panel'), panel: ids(PANELS), heading: text, text }, { requiredKeys: ['type', 'panel'] }),
      fc.record({ type: fc.constant('question'), question: ids(QUESTIONS), seed: text, heading: text },
        { requiredKeys: ['type', 'question'] }),
    );
    check(fc.property(fc.array(item, { maxLength: 5 }), text, (items, title) => {
      const lecture = lectureOf(items, title);
      const html = deck(lecture);
      expectOnlyDeckMarkup(html);
      expect(slidesOf(html).match(/ data-item="/g) ?? []).toHaveLength(readLecture(lecture).lecture.items.length);
    }), 60);
  });

  it('every question of the bank: its prompt, its options, and below it the answer the homework page reveals', () => {
    const lecture = lectureOf(QUESTIONS.map((q) => ({ type: 'question', question: q.id })));
    const html = deck(lecture);
    expectOnlyDeckMarkup(html);
    for (const question of QUESTIONS) {
      const params = questionParams(question, DEFAULT_QUESTION_SEED);
      const at = html.indexOf(`data-question="${question.id}"`);
      const slide = html.slice(at, html.indexOf('</section>\n</section>', at));
      expect(slide).toContain(subscriptedHtml(question.prompt(params)));
      if (question.kind === 'choice') {
        expect(slide.match(/<li>/g)).toHaveLength(question.options(params).length);
        expect(slide).toContain(`<strong>${subscriptedHtml(trueOption(question, params).text(params))}</strong>`);
      } else {
        const value = formatValue(question, expectedValue(question, params));
        expect(slide).toContain(`The computed answer is <strong>${escapeHtml(value)}</strong>`);
      }
      expect(slide).toMatch(new RegExp(`data-src="offline/embed.html\\?panel=${question.panel}[&"]`));
    }
    // The seed decides the numbers, as on the homework page.
    const seeded = (seed) => deck(lectureOf([{ type: 'question', question: 'brewster-predict', seed }]));
    expect(seeded('a')).toBe(seeded('a'));
    expect(new Set(['a', 'b', 'c', 'd', 'e'].map(seeded)).size).toBeGreaterThan(1);
  });

  it('carries reveal.js inline, and no inline text can end its element early', () => {
    const html = lectureDeckHtml(composed, {
      revealJs: 'var s = "</script><script>alert(1)</script>"; // <!-- x',
      revealCss: 'a::after{content:"</style><script>alert(1)</script>"}',
    });
    expect(html).toContain('var s = "<\\/script><script>alert(1)<\\/script>"; // <\\!-- x');
    expect(html).toContain('a::after{content:"<\\/style><script>alert(1)</script>"}');
    expect(html.match(/<\/script>/g)).toHaveLength(2 + 1); // the deck's two, and the text in the CSS (no end of a script there)
    expect(html.match(/<\/style>/g)).toHaveLength(3); // reveal's, the deck's, and KaTeX's (the lecture has math)
    expect(/<style>([^]*?)<\/style>/.exec(html)[1]).toBe('a::after{content:"<\\/style><script>alert(1)</script>"}'); // the CSS whole
    // The real reveal.js by default: its UMD build, which sets window.Reveal.
    const real = lectureDeckHtml(composed);
    expect(real).toMatch(/<script>\/\*!\n \* reveal\.js/);
    expect(real.length).toBeGreaterThan(100_000);
    expect(real).not.toMatch(/https?:\/\/(?!revealjs\.com|hakim\.se)[^\s"')]*\.(js|css)/); // nothing fetched from a CDN
  });

  it('a panel whose page did not load: the deck carries the lab\'s notice for it, in the page\'s language', () => {
    // The words the deck's script puts in a frame's place (its JSON), where the panels are and what to do.
    const missing = (html) => JSON.parse(/var MISSING = (\{.*\});/.exec(html)[1]);
    expect(missing(deck(composed))).toEqual({
      title: 'The panel could not be shown here.',
      why: expect.stringMatching(/^Its page, offline\/embed\.html, did not load: .*offline folder \(dist\/offline/),
    });
    expect(missing(deck(composed, { embedUrl: 'https://lab.example/embed.html' })).why)
      .toMatch(/^Its page, https:\/\/lab\.example\/embed\.html, did not load: .*needs the network\.$/);
    // An address that could end the script stays inside its string.
    const odd = deck(composed, { embedUrl: 'x</script><script>alert(1)</script>' });
    expect(odd.match(/<\/script>/g)).toHaveLength(2);
    expect(missing(odd).why).toContain('x</script><script>alert(1)</script>');
    try {
      setCatalogue('es', spanish);
      expect(missing(deck(composed)).title).toBe('El panel no se ha podido mostrar aquí.');
      expect(missing(deck(composed)).why).toMatch(/^Su página, offline\/embed\.html, no se ha cargado/);
    } finally {
      setCatalogue('en', null);
    }
  });

  it('embedSource writes what differs from the defaults, as a share link does', () => {
    expect(embedSource('e.html', 'schlick')).toBe('e.html?panel=schlick');
    expect(embedSource('e.html', 'schlick', { state: { nT: 1.7 }, lock: ['nT'], theme: 'light' }))
      .toBe('e.html?panel=schlick&nT=1.7&lock=nT&theme=light');
  });
});
